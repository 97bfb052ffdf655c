// What a picture of a run is drawn from, as plain data (no deal.II): the part as small polygons
// (2D: the cells cut into sub-cells, so that curved cells look curved; 3D: the outer surface's
// faces cut the same way), each corner with its reference position, displacement and the value
// that colours it, and in 2D the boundary as segments. Gathered to rank 0 by
// output/picture_sampling.h, drawn by output/part_picture.h.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace compliant
{
  struct PictureCorner
  {
    std::array<double, 3> x{};     // reference position
    std::array<double, 3> u{};     // displacement
    double                value = 0;
  };

  struct PictureGeometry
  {
    unsigned int dim = 2;
    // Corners counter-clockwise seen from outside (3D) or from +z (2D).
    std::vector<std::vector<PictureCorner>>  polygons;
    std::vector<std::array<PictureCorner, 2>> outline; // 2D: boundary segments
  };

  // What is written on a picture.
  struct PictureLabels
  {
    std::string title;                // first line
    std::string subtitle;             // second line (case, load, ...)
    std::string value_name;           // "von Mises stress"
    std::string value_unit;           // "MPa"; "" for a normalized value
    std::string length_unit;          // "mm"
    bool        has_peak = false;     // mark the peak (value and where)
    double      peak_value = 0;
    std::array<double, 3> peak_position{};
    // Modes have no true scale: drawn with their largest displacement this fraction of the
    // part's size. 0: true scale, magnified only when displacements are small.
    double      mode_amplitude = 0;
  };

  // Flattened for MPI (one vector of doubles per rank) and back.
  std::vector<double> flatten(const PictureGeometry &geometry);
  void                append_flattened(const std::vector<double> &data, PictureGeometry &geometry);
} // namespace compliant
