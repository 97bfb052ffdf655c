#include "output/report_page.h"
#include "output/svg_style.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace compliant
{
  namespace
  {
    std::string base64(const std::string &data)
    {
      static const char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      std::string       out;
      out.reserve((data.size() + 2) / 3 * 4);
      for (std::size_t i = 0; i < data.size(); i += 3)
        {
          const unsigned int n = static_cast<unsigned char>(data[i]) << 16 |
                                 (i + 1 < data.size() ? static_cast<unsigned char>(data[i + 1]) << 8 : 0) |
                                 (i + 2 < data.size() ? static_cast<unsigned char>(data[i + 2]) : 0);
          out += table[n >> 18 & 63];
          out += table[n >> 12 & 63];
          out += i + 1 < data.size() ? table[n >> 6 & 63] : '=';
          out += i + 2 < data.size() ? table[n & 63] : '=';
        }
      return out;
    }

    // As the terminal table prints it (8 significant digits).
    std::string shown(const double v)
    {
      if (!std::isfinite(v))
        return "n/a";
      std::ostringstream s;
      s << std::setprecision(8) << v;
      return s.str();
    }

    // As summary.json holds it (12 significant digits).
    std::string full(const double v)
    {
      std::ostringstream s;
      s << std::setprecision(12) << v;
      return s.str();
    }

    bool ends_with(const std::string &s, const std::string &suffix)
    {
      return s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
    }

    bool is_timing(const std::string &name)
    {
      return name.rfind("time_", 0) == 0 || name.rfind("memory_", 0) == 0;
    }

    const char *style = R"(<style>
body{font-family:Helvetica,Arial,sans-serif;margin:24px auto;max-width:1000px;color:#1a1a1a;line-height:1.4}
h1{font-size:22px;margin-bottom:4px}h2{font-size:17px;border-bottom:1px solid #ccc;padding-bottom:3px;margin-top:28px}
table{border-collapse:collapse;font-size:13px;margin:6px 0}td,th{border:1px solid #d4d4d4;padding:3px 8px;text-align:left}
th{background:#f0f0f0}td.num{text-align:right;font-family:Menlo,Consolas,monospace}
.warning{background:#fff4e0;border-left:4px solid #e08a00;padding:4px 10px;margin:4px 0;font-size:13px}
.meta{color:#555;font-size:13px}pre{background:#f6f6f6;padding:10px;font-size:12px;overflow-x:auto}
figure{margin:10px 0}figcaption{font-size:13px;color:#444}img{max-width:100%;border:1px solid #e4e4e4}
</style>
)";

    std::string setting(const RunSummary &s, const std::string &key)
    {
      const auto it = s.settings.find(key);
      return it == s.settings.end() ? "" : it->second;
    }

    void quantity_table(const RunSummary &s, const bool timings, std::ostream &out)
    {
      out << "<table class=\"" << (timings ? "timings" : "quantities") << "\"><tr><th>quantity</th><th>value</th>"
          << (timings ? "" : "<th>estimated discretization error</th>") << "</tr>\n";
      for (const auto &[name, value] : s.quantities)
        {
          if (is_timing(name) != timings || ends_with(name, "_error_estimate") ||
              ends_with(name, "_error_estimate_absolute"))
            continue;
          out << "<tr data-quantity=\"" << escape_xml(name) << "\" data-value=\"" << full(value) << "\"><td>"
              << escape_xml(name) << "</td><td class=\"num\">" << shown(value) << "</td>";
          if (!timings)
            {
              const auto relative = s.quantities.find(name + "_error_estimate");
              const auto absolute = s.quantities.find(name + "_error_estimate_absolute");
              out << "<td class=\"num\">";
              if (relative != s.quantities.end() && (relative->second < 1 || absolute == s.quantities.end()))
                out << short_number(100 * relative->second, 2) << " %";
              else if (absolute != s.quantities.end())
                out << short_number(absolute->second, 2) << " (absolute)";
              out << "</td>";
            }
          out << "</tr>\n";
        }
      out << "</table>\n";
    }

    void comparison_section(const RunSummary &s, std::ostream &out)
    {
      out << "<h2>Comparison with closed forms</h2>\n";
      if (s.comparisons.empty())
        {
          out << "<p class=\"meta\">The case asks for no comparison (Comparison/Checks).</p>\n";
          return;
        }
      out << "<table class=\"comparisons\"><tr><th>quantity</th><th>closed form</th><th>FE</th><th>closed form value</th>"
             "<th>relative difference</th></tr>\n";
      for (const auto &c : s.comparisons)
        {
          std::ostringstream diff;
          diff << std::showpos << std::fixed << std::setprecision(3) << 100 * c.relative_difference << " %";
          out << "<tr data-comparison=\"" << escape_xml(c.quantity) << "\" data-computed=\"" << full(c.computed)
              << "\" data-reference=\"" << full(c.reference) << "\"><td>" << escape_xml(c.quantity) << "</td><td>"
              << escape_xml(c.formula) << "</td><td class=\"num\">" << shown(c.computed) << "</td><td class=\"num\">"
              << shown(c.reference) << "</td><td class=\"num\">" << diff.str() << "</td></tr>\n";
        }
      out << "</table>\n";
      for (const auto &c : s.comparisons)
        for (const auto &w : c.warnings)
          out << "<div class=\"warning\"><b>Validity warning</b> (" << escape_xml(c.formula) << ", "
              << escape_xml(c.quantity) << "): " << escape_xml(w) << "</div>\n";
    }
  } // namespace

  std::string report_html(const RunSummary &s, const std::string &case_text,
                          const std::vector<Picture> &pictures, const double picture_seconds)
  {
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>"
        << escape_xml(s.case_file) << " - compliant report</title>\n"
        << style << "</head><body>\n<h1>" << escape_xml(s.case_file) << "</h1>\n<p class=\"meta\">"
        << escape_xml(setting(s, "analysis")) << " analysis, " << escape_xml(setting(s, "model"))
        << "; written by compliant beside summary.json, from the same values.";
    if (!setting(s, "status").empty())
      out << " Status: <b>" << escape_xml(setting(s, "status")) << "</b>.";
    out << "</p>\n";

    std::size_t n_warnings = 0;
    for (const auto &c : s.comparisons)
      n_warnings += c.warnings.size();
    if (n_warnings > 0)
      out << "<div class=\"warning\">" << n_warnings << " validity warning" << (n_warnings > 1 ? "s" : "")
          << " on the closed-form comparisons: see below.</div>\n";

    if (!pictures.empty())
      out << "<h2>Pictures</h2>\n";
    for (const auto &p : pictures)
      out << "<figure><img alt=\"" << escape_xml(p.caption) << "\" data-file=\"" << escape_xml(p.file)
          << "\" src=\"data:image/svg+xml;base64," << base64(p.svg) << "\"><figcaption>" << escape_xml(p.caption)
          << " (" << escape_xml(p.file) << " beside this page)</figcaption></figure>\n";

    out << "<h2>Model, mesh and solver</h2>\n<table class=\"settings\">";
    for (const auto &[key, value] : s.settings)
      out << "<tr><th>" << escape_xml(key) << "</th><td>" << escape_xml(value) << "</td></tr>\n";
    out << "</table>\n";
    if (!s.parameters.empty())
      {
        out << "<h2>Geometry parameters</h2>\n<table class=\"parameters\">";
        for (const auto &[key, value] : s.parameters)
          out << "<tr data-parameter=\"" << escape_xml(key) << "\" data-value=\"" << full(value) << "\"><th>"
              << escape_xml(key) << "</th><td class=\"num\">" << shown(value) << "</td></tr>\n";
        out << "</table>\n";
      }
    out << "<h2>Quantities</h2>\n";
    quantity_table(s, false, out);
    comparison_section(s, out);
    out << "<h2>Timings and memory</h2>\n";
    quantity_table(s, true, out);
    out << "<p class=\"meta\">Pictures and this page: " << short_number(picture_seconds, 2)
        << " s (not in summary.json).</p>\n";
    out << "<h2>Case file</h2>\n<p class=\"meta\">As on disk; values given with --set on the command line "
           "are not in it (the geometry parameters and settings above are the run's own).</p>\n<pre>" << escape_xml(case_text) << "</pre>\n</body></html>\n";
    return out.str();
  }
} // namespace compliant
