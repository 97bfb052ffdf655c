#include "output/part_picture.h"
#include "output/svg_style.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace compliant
{
  namespace
  {
    using Vec = std::array<double, 3>;

    double dot(const Vec &a, const Vec &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    Vec normalized(const Vec &a)
    {
      const double n = std::sqrt(dot(a, a));
      return {a[0] / n, a[1] / n, a[2] / n};
    }

    Vec cross(const Vec &a, const Vec &b)
    {
      return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    // Screen right, screen up, towards the viewer.
    struct View
    {
      Vec         right, up, towards;
      std::string name;
    };

    View view_from(const Vec &direction, const std::string &name)
    {
      const Vec towards = normalized(direction);
      // z up on the screen unless looking along z.
      const Vec world_up = std::abs(towards[2]) > 0.99 ? Vec{0, 1, 0} : Vec{0, 0, 1};
      const Vec right    = normalized(cross(world_up, towards));
      return {right, cross(towards, right), towards, name};
    }

    Vec position(const PictureCorner &c, const double scale)
    {
      return {c.x[0] + scale * c.u[0], c.x[1] + scale * c.u[1], c.x[2] + scale * c.u[2]};
    }

    struct Box
    {
      double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
      void   add(double x, double y)
      {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    };

    // Maps a view's model coordinates into a pixel rectangle, y down, aspect kept.
    struct Frame
    {
      double scale = 1, ox = 0, oy = 0;
      double px(const Vec &p, const View &v) const { return ox + scale * dot(p, v.right); }
      double py(const Vec &p, const View &v) const { return oy - scale * dot(p, v.up); }
    };

    Box projected_box(const PictureGeometry &g, const View &v, const double scale)
    {
      Box box;
      const auto add = [&](const PictureCorner &c) {
        for (const double s : {0.0, scale})
          box.add(dot(position(c, s), v.right), dot(position(c, s), v.up));
      };
      for (const auto &polygon : g.polygons)
        for (const auto &c : polygon)
          add(c);
      for (const auto &segment : g.outline)
        for (const auto &c : segment)
          add(c);
      return box;
    }

    Frame fit(const Box &box, const double left, const double top, const double width,
              const double height)
    {
      Frame        f;
      const double w = std::max(box.x1 - box.x0, 1e-300), h = std::max(box.y1 - box.y0, 1e-300);
      f.scale        = std::min(width / w, height / h);
      f.ox           = left + 0.5 * (width - f.scale * w) - f.scale * box.x0;
      f.oy           = top + 0.5 * (height - f.scale * h) + f.scale * box.y1;
      return f;
    }

    // x with one decimal (pixels): what the picture needs, written without printf (thousands of
    // points per picture).
    void append_pixel(const double x, std::string &out)
    {
      const long long tenths = std::llround(std::isfinite(x) ? 10 * x : 0.0);
      char            text[24];
      auto            end = std::to_chars(text, text + sizeof(text), std::llabs(tenths) / 10).ptr;
      if (tenths < 0)
        out += '-';
      out.append(text, end);
      out += '.';
      out += static_cast<char>('0' + std::llabs(tenths) % 10);
    }

    void path_of(const std::vector<PictureCorner> &polygon, const View &v, const Frame &f,
                 const double scale, std::ostream &out)
    {
      std::string text;
      char        command = 'M';
      for (const auto &c : polygon)
        {
          const Vec p = position(c, scale);
          text += command;
          append_pixel(f.px(p, v), text);
          text += ' ';
          append_pixel(f.py(p, v), text);
          command = 'L';
        }
      out << text << 'Z';
    }

    // Signed area on the screen (> 0: counter-clockwise, facing the viewer) and mean depth.
    std::pair<double, double> facing_and_depth(const std::vector<PictureCorner> &polygon,
                                               const View &v, const double scale)
    {
      double area = 0, depth = 0;
      for (std::size_t k = 0; k < polygon.size(); ++k)
        {
          const Vec a = position(polygon[k], scale), b = position(polygon[(k + 1) % polygon.size()], scale);
          area += dot(a, v.right) * dot(b, v.up) - dot(b, v.right) * dot(a, v.up);
          depth += dot(a, v.towards);
        }
      return {area, depth / polygon.size()};
    }

    // Flat shading of a polygon facing the viewer: its normal against the view direction.
    double shade_of(const std::vector<PictureCorner> &polygon, const View &v, const double scale)
    {
      Vec n{0, 0, 0};
      for (std::size_t k = 0; k < polygon.size(); ++k)
        {
          const Vec a = position(polygon[k], scale), b = position(polygon[(k + 1) % polygon.size()], scale);
          const Vec c = cross(a, b);
          n           = {n[0] + c[0], n[1] + c[1], n[2] + c[2]};
        }
      const double length = std::sqrt(dot(n, n));
      return length > 0 ? 0.55 + 0.45 * std::abs(dot(n, v.towards)) / length : 1.0;
    }

    struct Range
    {
      double low = 0, high = 1;
      double fraction(double v) const { return high > low ? (v - low) / (high - low) : 0.5; }
    };

    std::size_t nearest_corner(const PictureGeometry &g, const Vec &x, std::size_t &polygon_index)
    {
      double      best = std::numeric_limits<double>::max();
      std::size_t corner = 0;
      for (std::size_t p = 0; p < g.polygons.size(); ++p)
        for (std::size_t k = 0; k < g.polygons[p].size(); ++k)
          {
            const auto  &c = g.polygons[p][k].x;
            const double d = (c[0] - x[0]) * (c[0] - x[0]) + (c[1] - x[1]) * (c[1] - x[1]) +
                             (c[2] - x[2]) * (c[2] - x[2]);
            if (d < best)
              best = d, polygon_index = p, corner = k;
          }
      return corner;
    }

    // One view: the undeformed part in grey, the deformed part in colour bands on top, the peak.
    void draw_view(const PictureGeometry &g, const PictureLabels &labels, const View &v,
                   const Frame &f, const double scale, const Range &range, std::ostream &out)
    {
      const bool three_d = g.dim == 3;
      // Painter's order: visible polygons from back to front.
      const auto visible = [&](double s) {
        std::vector<std::pair<double, std::size_t>> order;
        for (std::size_t p = 0; p < g.polygons.size(); ++p)
          {
            if (!three_d) // flat: any order, nothing hidden
              {
                order.emplace_back(0.0, p);
                continue;
              }
            const auto [area, depth] = facing_and_depth(g.polygons[p], v, s);
            if (area > 0)
              order.emplace_back(depth, p);
          }
        if (three_d)
          std::sort(order.begin(), order.end());
        return order;
      };
      if (three_d)
        {
          out << "<g fill=\"#d9d9d9\" stroke=\"#c4c4c4\" stroke-width=\"0.3\">";
          for (const auto &[depth, p] : visible(0.0))
            out << "<path d=\"", path_of(g.polygons[p], v, f, 0.0, out), out << "\"/>";
          out << "</g>\n";
        }
      else
        {
          out << "<path fill=\"none\" stroke=\"#9a9a9a\" stroke-width=\"1\" stroke-dasharray=\"4 3\" d=\"";
          for (const auto &segment : g.outline)
            path_of({segment[0], segment[1]}, v, f, 0.0, out);
          out << "\"/>\n";
        }
      std::vector<std::string> flat; // the bands' colours, unshaded
      for (unsigned int k = 0; k < colour_bands; ++k)
        {
          double r, gr, b;
          band_colour((k + 0.5) / colour_bands, r, gr, b);
          flat.push_back(hex_colour(r, gr, b));
        }
      // Fill and hairline stroke in one colour (currentColor) hide the seams between polygons.
      out << "<g fill=\"currentColor\" stroke=\"currentColor\" stroke-width=\"0.4\" stroke-linejoin=\"round\">";
      for (const auto &[depth, p] : visible(scale))
        {
          const auto  &polygon = g.polygons[p];
          double       value   = 0;
          for (const auto &c : polygon)
            value += c.value;
          double r, gr, b;
          const double t = range.fraction(value / polygon.size());
          band_colour(t, r, gr, b);
          out << "<path color=\""
              << (three_d ? hex_colour(r, gr, b, shade_of(polygon, v, scale)) :
                            flat[std::min<unsigned int>(colour_bands - 1, std::max(0.0, t) * colour_bands)])
              << "\" d=\"";
          path_of(polygon, v, f, scale, out);
          out << "\"/>";
        }
      out << "</g>\n";
      if (!three_d)
        {
          out << "<path fill=\"none\" stroke=\"#202020\" stroke-width=\"0.8\" d=\"";
          for (const auto &segment : g.outline)
            path_of({segment[0], segment[1]}, v, f, scale, out);
          out << "\"/>\n";
        }
      if (labels.has_peak && !g.polygons.empty())
        {
          std::size_t  p = 0;
          const auto   k = nearest_corner(g, labels.peak_position, p);
          const Vec    x = position(g.polygons[p][k], scale);
          const double px = f.px(x, v), py = f.py(x, v);
          out << "<g class=\"peak\"><circle cx=\"" << short_number(px, 5) << "\" cy=\"" << short_number(py, 5)
              << "\" r=\"6\" fill=\"none\" stroke=\"#000\" stroke-width=\"2\"/>"
              << "<circle cx=\"" << short_number(px, 5) << "\" cy=\"" << short_number(py, 5)
              << "\" r=\"2\" fill=\"#000\"/></g>\n";
        }
    }

    void draw_colour_bar(const PictureLabels &labels, const Range &range, const double left,
                         const double top, const double height, std::ostream &out)
    {
      const double band = height / colour_bands;
      out << "<g font-size=\"11\">";
      for (unsigned int k = 0; k < colour_bands; ++k)
        {
          double r, g, b;
          band_colour((k + 0.5) / colour_bands, r, g, b);
          out << "<rect x=\"" << left << "\" y=\"" << short_number(top + height - (k + 1) * band, 5)
              << "\" width=\"18\" height=\"" << short_number(band + 0.3, 5) << "\" fill=\""
              << hex_colour(r, g, b) << "\"/>";
        }
      for (unsigned int k = 0; k <= colour_bands; k += 2)
        out << "<text x=\"" << left + 24 << "\" y=\"" << short_number(top + height - k * band + 4, 5)
            << "\">" << short_number(range.low + (range.high - range.low) * k / colour_bands) << "</text>";
      out << "<text x=\"" << left << "\" y=\"" << top - 10 << "\" font-weight=\"bold\">"
          << escape_xml(labels.value_name)
          << (labels.value_unit.empty() ? "" : " [" + escape_xml(labels.value_unit) + "]") << "</text></g>\n";
    }

    double largest_displacement(const PictureGeometry &g)
    {
      double largest = 0;
      for (const auto &polygon : g.polygons)
        for (const auto &c : polygon)
          largest = std::max(largest, std::sqrt(dot(c.u, c.u)));
      for (const auto &segment : g.outline)
        for (const auto &c : segment)
          largest = std::max(largest, std::sqrt(dot(c.u, c.u)));
      return largest;
    }

    double part_size(const PictureGeometry &g)
    {
      Vec lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
      for (const auto &polygon : g.polygons)
        for (const auto &c : polygon)
          for (unsigned int d = 0; d < 3; ++d)
            lo[d] = std::min(lo[d], c.x[d]), hi[d] = std::max(hi[d], c.x[d]);
      const Vec diagonal{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
      return g.polygons.empty() ? 1.0 : std::sqrt(dot(diagonal, diagonal));
    }

    // The 3D views: from the octant on the peak's side of the part's centre, and the opposite.
    std::vector<View> views_of(const PictureGeometry &g, const PictureLabels &labels)
    {
      if (g.dim == 2)
        return {view_from({0, 0, 1}, "")};
      Vec centre{0, 0, 0};
      std::size_t n = 0;
      for (const auto &polygon : g.polygons)
        for (const auto &c : polygon)
          centre = {centre[0] + c.x[0], centre[1] + c.x[1], centre[2] + c.x[2]}, ++n;
      Vec side{1, -1, 1};
      if (labels.has_peak && n > 0)
        for (unsigned int d = 0; d < 3; ++d)
          side[d] = labels.peak_position[d] >= centre[d] / n ? 1 : -1;
      const auto name = [](const Vec &d) {
        std::string text = "seen from (";
        for (unsigned int k = 0; k < 3; ++k)
          text += std::string(k ? " " : "") + (d[k] > 0 ? "+" : "-") + "xyz"[k];
        return text + ")";
      };
      const Vec opposite{-side[0], -side[1], -side[2]};
      return {view_from({side[0], side[1], 0.8 * side[2]}, name(side) + (labels.has_peak ? ", the peak's side" : "")),
              view_from({opposite[0], opposite[1], 0.8 * opposite[2]}, name(opposite))};
    }
  } // namespace

  double deformation_scale(const PictureGeometry &g, const PictureLabels &labels)
  {
    const double largest = largest_displacement(g), size = part_size(g);
    if (largest <= 0 || !std::isfinite(largest))
      return 1.0;
    if (labels.mode_amplitude > 0)
      return labels.mode_amplitude * size / largest;
    if (largest >= 0.02 * size)
      return 1.0;
    const double wanted = 0.1 * size / largest;
    const double decade = std::pow(10.0, std::floor(std::log10(wanted)));
    for (const double step : {5.0, 2.0, 1.0})
      if (step * decade <= wanted)
        return step * decade;
    return decade;
  }

  std::string draw_part(const PictureGeometry &g, const PictureLabels &labels)
  {
    const double scale = deformation_scale(g, labels);
    Range        range{std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
    for (const auto &polygon : g.polygons)
      for (const auto &c : polygon)
        range.low = std::min(range.low, c.value), range.high = std::max(range.high, c.value);
    if (labels.has_peak)
      range.high = std::max(range.high, labels.peak_value);
    if (g.polygons.empty())
      range = {0, 1};

    const auto   views = views_of(g, labels);
    const double width = 900, bar = 150, top = 78;
    const double view_width = (width - bar - 30) / views.size();
    std::vector<Box> boxes;
    double           height = 200;
    for (const auto &v : views)
      {
        boxes.push_back(projected_box(g, v, scale));
        const Box &b = boxes.back();
        height = std::max(height, std::min(560.0, view_width * (b.y1 - b.y0) / std::max(b.x1 - b.x0, 1e-300)));
      }
    const double total = top + height + 50;
    std::ostringstream out;
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << total
        << "\" viewBox=\"0 0 " << width << " " << total << "\" font-family=\"Helvetica, Arial, sans-serif\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n"
        << "<text x=\"16\" y=\"26\" font-size=\"17\" font-weight=\"bold\">" << escape_xml(labels.title) << "</text>\n"
        << "<text x=\"16\" y=\"46\" font-size=\"12\">" << escape_xml(labels.subtitle) << "</text>\n";
    const double largest = largest_displacement(g);
    out << "<text x=\"16\" y=\"64\" font-size=\"12\">";
    if (labels.mode_amplitude > 0)
      out << "Mode shape drawn with its largest displacement " << short_number(100 * labels.mode_amplitude)
          << " % of the part's size; undeformed part in grey";
    else
      out << (scale == 1.0 ? std::string("Deformation at true scale") :
                             "Deformation magnified x " + short_number(scale, 6))
          << " (largest displacement " << short_number(largest) << " " << escape_xml(labels.length_unit)
          << "); undeformed part " << (g.dim == 2 ? "dashed" : "in grey");
    out << "</text>\n";
    for (std::size_t i = 0; i < views.size(); ++i)
      {
        const double left = 16 + i * view_width;
        const Frame  f    = fit(boxes[i], left + 10, top + 10, view_width - 20, height - 20);
        draw_view(g, labels, views[i], f, scale, range, out);
        if (!views[i].name.empty())
          out << "<text x=\"" << left + 10 << "\" y=\"" << top + height + 4 << "\" font-size=\"11\" fill=\"#555\">"
              << escape_xml(views[i].name) << "</text>\n";
      }
    draw_colour_bar(labels, range, width - bar + 10, top + 20, std::min(height - 30, 300.0), out);
    if (labels.has_peak)
      {
        std::ostringstream where;
        where << "(";
        for (unsigned int d = 0; d < g.dim; ++d)
          where << (d ? ", " : "") << short_number(labels.peak_position[d]);
        where << ")";
        out << "<text x=\"16\" y=\"" << total - 16 << "\" font-size=\"13\">"
            << "<tspan font-weight=\"bold\">&#9675; peak " << escape_xml(labels.value_name) << " "
            << short_number(labels.peak_value) << " " << escape_xml(labels.value_unit) << "</tspan> at "
            << where.str() << " " << escape_xml(labels.length_unit) << " (undeformed position)</text>\n";
      }
    out << "</svg>\n";
    return out.str();
  }
} // namespace compliant
