#include "output/curve_chart.h"
#include "output/svg_style.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <vector>

namespace compliant
{
  namespace
  {
    std::vector<std::string> split(const std::string &line)
    {
      std::vector<std::string> out;
      std::stringstream        s(line);
      std::string              cell;
      while (std::getline(s, cell, ','))
        out.push_back(cell);
      return out;
    }

    struct Column
    {
      std::string         name;
      std::vector<double> values;
      double              range() const
      {
        const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
        return values.empty() ? 0 : *hi - *lo;
      }
    };

    bool starts(const std::string &s, const std::string &prefix)
    {
      return s.rfind(prefix, 0) == 0;
    }

    // The motion to plot: rotations first (a hinge is judged by its angle; a Derived angle in
    // degrees counts), then displacements, the one with the largest range of its kind.
    const Column *motion_column(const std::vector<Column> &columns)
    {
      const std::vector<std::function<bool(const std::string &)>> kinds{
        [](const std::string &n) { return starts(n, "rigid_rotation_") || starts(n, "rotation_"); },
        [](const std::string &n) { return n.size() > 4 && n.compare(n.size() - 4, 4, "_deg") == 0; },
        [](const std::string &n) { return starts(n, "displacement_") || starts(n, "mean_displacement_"); }};
      for (const auto &kind : kinds)
        {
          const Column *best = nullptr;
          for (const auto &c : columns)
            if (kind(c.name) && c.range() > 0 && (!best || c.range() > best->range()))
              best = &c;
          if (best)
            return best;
        }
      return nullptr;
    }

    // Round tick spacing (1, 2 or 5 x 10^k) for about five ticks.
    double tick_step(const double range)
    {
      const double raw    = range > 0 ? range / 5 : 1;
      const double decade = std::pow(10.0, std::floor(std::log10(raw)));
      for (const double step : {1.0, 2.0, 5.0})
        if (step * decade >= raw)
          return step * decade;
      return 10 * decade;
    }
  } // namespace

  std::string draw_load_displacement(const std::string &csv_text, const std::string &title,
                                     const std::string &length_unit)
  {
    std::istringstream  in(csv_text);
    std::string         line;
    std::vector<Column> columns;
    if (!std::getline(in, line))
      return "";
    for (const auto &name : split(line))
      columns.push_back({name, {}});
    while (std::getline(in, line))
      {
        const auto cells = split(line);
        if (cells.size() != columns.size())
          continue;
        for (std::size_t c = 0; c < cells.size(); ++c)
          columns[c].values.push_back(std::strtod(cells[c].c_str(), nullptr));
      }
    const auto load = std::find_if(columns.begin(), columns.end(), [](const Column &c) { return c.name == "load_factor"; });
    const Column *x = motion_column(columns);
    if (load == columns.end() || !x || load->values.size() < 2)
      return "";
    const bool   radians = x->name.find("rotation") != std::string::npos;
    const bool   angle   = radians || x->name.find("_deg") != std::string::npos;
    const double factor  = radians ? 180 / M_PI : 1.0; // rotations in degrees
    std::vector<double> xs;
    for (const double v : x->values)
      xs.push_back(factor * v);
    const auto [x_lo, x_hi] = std::minmax_element(xs.begin(), xs.end());
    const double xmin = std::min(0.0, *x_lo), xmax = std::max(0.0, *x_hi);
    const double ymax = std::max(1e-300, *std::max_element(load->values.begin(), load->values.end()));
    const double ymin = std::min(0.0, *std::min_element(load->values.begin(), load->values.end()));
    const double left = 80, top = 50, w = 560, h = 320;
    const auto   px = [&](double v) { return left + w * (v - xmin) / std::max(xmax - xmin, 1e-300); };
    const auto   py = [&](double v) { return top + h - h * (v - ymin) / std::max(ymax - ymin, 1e-300); };

    std::ostringstream out;
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"680\" height=\"440\" viewBox=\"0 0 680 440\" "
           "font-family=\"Helvetica, Arial, sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n"
        << "<text x=\"16\" y=\"24\" font-size=\"15\" font-weight=\"bold\">" << escape_xml(title) << "</text>\n";
    out << "<g stroke=\"#ddd\">";
    const double xs_step = tick_step(xmax - xmin), ys_step = tick_step(ymax - ymin);
    std::ostringstream labels;
    for (double t = std::ceil(xmin / xs_step) * xs_step; t <= xmax + 1e-9 * xs_step; t += xs_step)
      {
        out << "<line x1=\"" << px(t) << "\" y1=\"" << top << "\" x2=\"" << px(t) << "\" y2=\"" << top + h << "\"/>";
        labels << "<text x=\"" << px(t) << "\" y=\"" << top + h + 16 << "\" text-anchor=\"middle\">"
               << short_number(std::abs(t) < 1e-12 * xs_step ? 0.0 : t) << "</text>";
      }
    for (double t = std::ceil(ymin / ys_step) * ys_step; t <= ymax + 1e-9 * ys_step; t += ys_step)
      {
        out << "<line x1=\"" << left << "\" y1=\"" << py(t) << "\" x2=\"" << left + w << "\" y2=\"" << py(t) << "\"/>";
        labels << "<text x=\"" << left - 6 << "\" y=\"" << py(t) + 4 << "\" text-anchor=\"end\">"
               << short_number(std::abs(t) < 1e-12 * ys_step ? 0.0 : t) << "</text>";
      }
    out << "</g>\n" << labels.str() << "\n<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << w
        << "\" height=\"" << h << "\" fill=\"none\" stroke=\"#333\"/>\n<polyline fill=\"none\" stroke=\"#1f4e9c\" stroke-width=\"2\" points=\"";
    if (load->values.front() > 0) // the path starts unloaded
      out << short_number(px(0), 6) << "," << short_number(py(0), 6) << " ";
    for (std::size_t i = 0; i < xs.size(); ++i)
      out << short_number(px(xs[i]), 6) << "," << short_number(py(load->values[i]), 6) << " ";
    out << "\"/>\n<g fill=\"#1f4e9c\">";
    for (std::size_t i = 0; i < xs.size(); ++i)
      out << "<circle cx=\"" << short_number(px(xs[i]), 6) << "\" cy=\"" << short_number(py(load->values[i]), 6) << "\" r=\"3\"/>";
    out << "</g>\n<text x=\"" << left + w / 2 << "\" y=\"" << top + h + 40 << "\" text-anchor=\"middle\" font-size=\"12\">"
        << escape_xml(x->name) << (radians ? " [deg]" : angle ? "" : " [" + escape_xml(length_unit) + "]") << "</text>\n"
        << "<text transform=\"translate(24 " << top + h / 2 << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">"
           "load factor</text>\n</svg>\n";
    return out.str();
  }
} // namespace compliant
