#include "output/picture_geometry.h"

#include <stdexcept>

namespace compliant
{
  namespace
  {
    void put(const PictureCorner &c, std::vector<double> &out)
    {
      out.insert(out.end(), c.x.begin(), c.x.end());
      out.insert(out.end(), c.u.begin(), c.u.end());
      out.push_back(c.value);
    }

    PictureCorner take(const std::vector<double> &data, std::size_t &i)
    {
      if (i + 7 > data.size())
        throw std::runtime_error("picture geometry: truncated data");
      PictureCorner c;
      for (unsigned int d = 0; d < 3; ++d)
        c.x[d] = data[i + d];
      for (unsigned int d = 0; d < 3; ++d)
        c.u[d] = data[i + 3 + d];
      c.value = data[i + 6];
      i += 7;
      return c;
    }
  } // namespace

  // Layout: n_polygons, then per polygon its corner count and corners; then n_segments and their
  // two corners each.
  std::vector<double> flatten(const PictureGeometry &g)
  {
    std::vector<double> out;
    out.push_back(g.polygons.size());
    for (const auto &polygon : g.polygons)
      {
        out.push_back(polygon.size());
        for (const auto &c : polygon)
          put(c, out);
      }
    out.push_back(g.outline.size());
    for (const auto &segment : g.outline)
      for (const auto &c : segment)
        put(c, out);
    return out;
  }

  void append_flattened(const std::vector<double> &data, PictureGeometry &g)
  {
    if (data.empty())
      return;
    std::size_t i = 0;
    const auto  n_polygons = static_cast<std::size_t>(data[i++]);
    for (std::size_t p = 0; p < n_polygons; ++p)
      {
        const auto                 n = static_cast<std::size_t>(data.at(i++));
        std::vector<PictureCorner> polygon;
        for (std::size_t k = 0; k < n; ++k)
          polygon.push_back(take(data, i));
        g.polygons.push_back(std::move(polygon));
      }
    const auto n_segments = static_cast<std::size_t>(data.at(i++));
    for (std::size_t s = 0; s < n_segments; ++s)
      {
        const PictureCorner a = take(data, i);
        g.outline.push_back({a, take(data, i)});
      }
  }
} // namespace compliant
