// `candela compare IMAGE.exr --reference REF.exr [--reference REF2.exr]`: one image's error
// against a reference, as --error-log defines it (film/error_metrics.h), for renders made by
// anything that writes RGB images (other renderers among them): relMSE, its raw value and the
// references' own noise when there are two, the outlier share, and the means.
#pragma once

namespace candela {

// argv[0] is "compare". Returns the exit code: 0, 1 (an image unreadable or the images
// mismatched), 2 (usage).
int runCompare(int argc, char** argv);

}  // namespace candela
