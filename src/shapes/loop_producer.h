// The choice of code behind the "loopsubdiv" shape, on its own so that the scene layer can carry
// it (BuildOptions, --subdiv) without the subdivision headers.
#pragma once

namespace candela {

// Which code refines (the command line's --subdiv): ours, the draft's algorithm (loop_subdiv.h), or
// OpenSubdiv 3.5 (Sdc::SCHEME_LOOP, VTX_BOUNDARY_EDGE_ONLY). Both apply the same rules, so both
// give the same surface and the same image.
enum class LoopProducer { Book, OpenSubdiv };

}  // namespace candela
