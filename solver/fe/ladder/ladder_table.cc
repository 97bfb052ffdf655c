#include "ladder/ladder_table.h"

#include "ladder/percent.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace compliant
{
  double Rung::stop_or_bare_estimate(const std::string &n) const
  {
    const auto stop = stop_estimates.find(n);
    if (stop != stop_estimates.end() && stop->second >= 0)
      return stop->second;
    const auto dual = dual_estimates.find(n);
    return dual != dual_estimates.end() ? dual->second : estimates.at(n).relative;
  }

  void print_rung(std::ostream &out, const Rung &rung, const std::size_t number, const bool show_adaptive)
  {
    out << "  (d) rung " << number << ": " << rung.model << ", degree " << rung.degree << ", refinements "
        << rung.refinements;
    if (show_adaptive)
      out << " + " << rung.adaptive_cycles << " adaptive";
    out << ", " << static_cast<long>(rung.dofs) << " DoFs, " << std::setprecision(3) << rung.seconds << " s;";
    for (const auto &[n, v] : rung.values)
      {
        const auto &e = rung.estimates.at(n);
        out << ' ' << n << " = " << std::setprecision(8) << v << " (estimate "
            << (e.available ? percent(e.relative) : std::string("-"));
        const auto stop = rung.stop_estimates.find(n);
        const auto dual = rung.dual_estimates.find(n);
        if (dual != rung.dual_estimates.end())
          out << ", dual-weighted " << percent(dual->second);
        if (e.available && stop != rung.stop_estimates.end() && stop->second > e.relative &&
            (dual == rung.dual_estimates.end() || stop->second != dual->second))
          out << ", untrusted: order not steady; bound used " << percent(stop->second);
        out << ")";
      }
    out << "; " << rung.decision << std::endl;
  }

  LadderRow ladder_row(const Rung &rung, const std::vector<std::string> &names, const bool plane_stress_prefix)
  {
    std::ostringstream head, tail;
    head << std::setprecision(10) << (plane_stress_prefix ? "plane stress " : "") << rung.model << ','
         << rung.degree << ',' << rung.refinements << ',' << rung.adaptive_cycles << ',' << rung.dofs << ','
         << rung.seconds;
    tail << std::setprecision(10);
    for (const auto &n : names)
      {
        const auto &e = rung.estimates.at(n);
        tail << ',' << rung.values.at(n) << ',';
        if (e.available)
          tail << e.relative;
        tail << ',';
        if (e.available || rung.dual_estimates.count(n) > 0)
          tail << rung.stop_or_bare_estimate(n);
      }
    return LadderRow{head.str(), rung.seconds, tail.str()};
  }

  void write_ladder_csv(const std::string &directory, const std::vector<std::string> &names,
                        const std::vector<LadderRow> &rows)
  {
    std::filesystem::create_directories(directory);
    std::ofstream out(directory + "/ladder.csv.tmp");
    out << "rung,model,degree,refinements,adaptive_cycles,dofs,seconds,cumulative_seconds";
    for (const auto &n : names)
      out << ',' << n << ",estimate_" << n << ",stop_estimate_" << n;
    out << "\n" << std::setprecision(10);
    double cumulative = 0;
    for (std::size_t k = 0; k < rows.size(); ++k)
      {
        cumulative += rows[k].seconds;
        out << k + 1 << ',' << rows[k].head << ',' << cumulative << rows[k].tail << "\n";
      }
    out.close();
    std::filesystem::rename(directory + "/ladder.csv.tmp", directory + "/ladder.csv");
  }
} // namespace compliant
