// Scenes shared by the photon-mapping tests.
#pragma once

#include <string>

namespace candela::test {

// A 2 x 2 x 2 room (matte 0.6) lit by a small two-sided area light under its ceiling, with a
// matte red sphere and a glass sphere on the floor; the camera is inside, so every pixel sees
// surfaces.
// sphereMaterial: the Material statement's arguments for the second sphere.
inline std::string causticRoom(int resolution, int spp, const std::string& integrator,
                               const std::string& sphereMaterial = "\"glass\"") {
  return "LookAt 0 0 -0.95  0 -0.2 1  0 1 0\nCamera \"perspective\" \"float fov\" [70]\n"
         "Film \"image\" \"integer xresolution\" [" +
         std::to_string(resolution) + "] \"integer yresolution\" [" + std::to_string(resolution) +
         "]\nSampler \"random\" \"integer pixelsamples\" [" + std::to_string(spp) +
         "]\nPixelFilter \"box\"\nSurfaceIntegrator " + integrator +
         "\nWorldBegin\n"
         "AttributeBegin\n"
         "  AreaLightSource \"diffuse\" \"rgb L\" [8 8 8] \"bool twosided\" \"true\"\n"
         "  Material \"matte\" \"rgb Kd\" [0 0 0]\n"
         "  Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
         "    \"point P\" [-0.3 0.99 -0.3  0.3 0.99 -0.3  0.3 0.99 0.3  -0.3 0.99 0.3]\n"
         "AttributeEnd\n"
         "Material \"matte\" \"rgb Kd\" [0.6 0.6 0.6]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3  4 5 6 4 6 7  8 9 10 8 10 11 "
         "12 13 14 12 14 15  16 17 18 16 18 19  20 21 22 20 22 23]\n"
         "  \"point P\" [-1 -1 -1  1 -1 -1  1 -1 1  -1 -1 1  -1 1 -1  1 1 -1  1 1 1  -1 1 1\n"
         "    -1 -1 1  1 -1 1  1 1 1  -1 1 1  -1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1\n"
         "    -1 -1 -1  -1 1 -1  -1 1 1  -1 -1 1  1 -1 -1  1 1 -1  1 1 1  1 -1 1]\n"
         "AttributeBegin\n  Material \"matte\" \"rgb Kd\" [0.7 0.2 0.2]\n"
         "  Translate -0.6 -0.7 0.5\n  Shape \"sphere\" \"float radius\" [0.3]\nAttributeEnd\n"
         "AttributeBegin\n  Material " +
         sphereMaterial +
         "\n  Translate 0.25 -0.6 0.3\n"
         "  Shape \"sphere\" \"float radius\" [0.4]\nAttributeEnd\nWorldEnd\n";
}

}  // namespace candela::test
