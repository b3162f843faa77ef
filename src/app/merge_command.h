// `candela merge -o out.exr pieces...`: assembles the pieces of a render split for a farm
// (`--tile`, `--frames`, `--sample-range`) into the images a single machine would have made, after
// checking that they belong together and that none is missing (app/piece_set.h).
#pragma once

namespace candela {

// argv[0] is "merge". Returns the exit code: 0, 1 (pieces refused or unreadable: nothing
// written), 2 (usage).
int runMerge(int argc, char** argv);

}  // namespace candela
