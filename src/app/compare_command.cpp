#include "app/compare_command.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "film/error_metrics.h"
#include "film/output/image_output.h"

namespace candela {

int runCompare(int argc, char** argv) {
  std::vector<std::string> images, references;
  int worst = 100;
  CLI::App app{
      "candela compare: each image's error against a reference, one line of key=value pairs per "
      "image: relmse (relMSE as --error-log defines it, with two references their mean and "
      "their own noise taken off), relmse_raw, reference_noise, mse, outlier_share (the share "
      "of relMSE in the --worst pixels), mean_r/g/b and ref_mean_r/g/b.",
      "candela compare"};
  app.add_option("images", images, "Images to measure (OpenEXR, or any format OpenImageIO reads)")
      ->required();
  app.add_option("--reference", references,
                 "Reference image; given twice, two independent renders of it (different seeds)")
      ->required()
      ->expected(1, 2);
  app.add_option("--worst", worst, "Pixels counted in the outlier share")
      ->check(CLI::NonNegativeNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    const ImageBuffer reference = readImage(references[0]);
    ImageBuffer second;
    if (references.size() > 1) second = readImage(references[1]);
    for (const std::string& path : images) {
      const ImageBuffer image = readImage(path);
      ImageComparison c;
      try {
        c = compareImages(image, reference, references.size() > 1 ? &second : nullptr, worst);
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
      }
      std::printf(
          "image=%s relmse=%.6g relmse_raw=%.6g reference_noise=%.6g mse=%.6g "
          "outlier_share=%.4f worst=%d mean_r=%.6g mean_g=%.6g mean_b=%.6g ref_mean_r=%.6g "
          "ref_mean_g=%.6g ref_mean_b=%.6g\n",
          path.c_str(), c.relmse, c.relmseRaw, c.referenceNoise, c.mse, c.outlierShare,
          c.worstPixels, c.mean[0], c.mean[1], c.mean[2], c.referenceMean[0], c.referenceMean[1],
          c.referenceMean[2]);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "candela compare: error: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace candela
