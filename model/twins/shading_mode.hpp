// Which pipeline shades (watkins_top's Phong parameter): Gouraud interpolates vertex shades;
// Phong interpolates vertex normals and applies Phong's eq. (3) at every pixel.
#pragma once

namespace watkins {

enum class ShadingMode { Gouraud, Phong };

}  // namespace watkins
