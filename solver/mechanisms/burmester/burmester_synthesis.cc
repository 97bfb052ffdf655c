// burmester_synthesis CASE [OUTPUT_DIR]: four-position synthesis of a four-bar (morphing-wing paper,
// seed 001), every candidate checked by forward kinematics for order, branch and circuit defects,
// ranked by the paper's criteria over the whole motion. Prints the ranked table; writes
// burmester_curves.csv, candidates.csv and mechanisms.csv (the ranked ones, for the charts).
// Case file: 'key = value' lines, '#' comments; keys below (see cases/morphing_wing/paper_table3.txt).
#include <mechanisms/burmester/candidate_mechanism.h>
#include <mechanisms/burmester/dyad_synthesis.h>
#include <text/text_utilities.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

using namespace compliant;
using namespace compliant::burmester;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  struct InputError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  struct Case
  {
    std::vector<PrecisionPosition> positions;
    unsigned int                   curve_samples = 720;
    unsigned int                   pair_dyads    = 160;
    SelectionCriteria              criteria;
  };

  double number(const std::string &text, const std::string &where)
  {
    std::istringstream in(text);
    double             v;
    std::string        rest;
    if (!(in >> v) || (in >> rest) || !std::isfinite(v))
      throw InputError(where + ": expected a finite number, got '" + text + "'");
    return v;
  }

  Case read_case(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("cannot open case file '" + file + "'");
    Case        c;
    std::string line;
    for (unsigned int n = 1; std::getline(in, line); ++n)
      {
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string::npos)
          continue;
        const auto eq = line.find('=');
        const std::string where = file + ":" + std::to_string(n);
        if (eq == std::string::npos)
          throw InputError(where + ": expected 'key = value'");
        const std::string key = text::trim(line.substr(0, eq)), value = text::trim(line.substr(eq + 1));
        if (key == "position")
          {
            std::istringstream v(value);
            double             x, y, angle;
            std::string        rest;
            if (!(v >> x >> y >> angle) || (v >> rest) || !std::isfinite(x + y + angle))
              throw InputError(where + ": 'position' expects three numbers: x y angle_in_degrees");
            c.positions.push_back({x, y, angle * pi / 180});
          }
        else if (key == "curve samples")
          c.curve_samples = static_cast<unsigned int>(number(value, where + " 'curve samples'"));
        else if (key == "pair dyads")
          c.pair_dyads = static_cast<unsigned int>(number(value, where + " 'pair dyads'"));
        else if (key == "transmission angle min")
          c.criteria.mu_low = number(value, where + " 'transmission angle min'") * pi / 180;
        else if (key == "transmission angle max")
          c.criteria.mu_high = number(value, where + " 'transmission angle max'") * pi / 180;
        else if (key == "minimum link length")
          c.criteria.min_link_length = number(value, where + " 'minimum link length'");
        else if (key == "maximum link length")
          c.criteria.max_link_length = number(value, where + " 'maximum link length'");
        else
          throw InputError(where + ": unknown key '" + key + "' (known: position, curve samples, pair dyads, "
                           "transmission angle min, transmission angle max, minimum link length, maximum link length)");
      }
    if (c.positions.size() != 4)
      throw InputError(file + ": expected exactly four 'position' lines, found " + std::to_string(c.positions.size()));
    if (c.curve_samples < 8 || c.curve_samples > 100000)
      throw InputError(file + ": 'curve samples' must be between 8 and 100000");
    if (c.pair_dyads < 2 || c.pair_dyads > 2000)
      throw InputError(file + ": 'pair dyads' must be between 2 and 2000");
    if (!(c.criteria.mu_low >= 0 && c.criteria.mu_low < c.criteria.mu_high && c.criteria.mu_high <= pi))
      throw InputError(file + ": transmission angle limits must satisfy 0 <= min < max <= 180");
    if (!(c.criteria.min_link_length >= 0 && c.criteria.max_link_length > c.criteria.min_link_length))
      throw InputError(file + ": link length limits must satisfy 0 <= minimum < maximum");
    return c;
  }

  double deg(double rad) { return rad * 180 / pi; }

  std::string row(const CandidateMechanism &m)
  {
    // Lengths and angles to 6 significant digits (mechanisms of 1e-3 chord and margins of 1e-3 degree
    // show), the pivots to full precision so that any check can rebuild the mechanism exactly.
    std::ostringstream s;
    s << std::setprecision(6) << m.lengths.ground << ',' << m.lengths.crank << ',' << m.lengths.coupler << ','
      << m.lengths.rocker << ',' << m.perimeter << ',' << four_bar::to_string(m.grashof.class_) << ','
      << deg(m.mu_min_at_positions) << ',' << deg(m.mu_max_at_positions) << ',' << deg(m.mu_min) << ','
      << deg(m.mu_max) << ',' << deg(m.input_sweep) << ',' << deg(m.toggle_margin_transmission) << ','
      << deg(m.toggle_margin_input) << ',' << std::setprecision(3) << m.position_error << ',' << m.angle_error
      << ',' << (m.defect.empty() ? "none" : m.defect) << std::setprecision(17);
    for (const Complex z : {m.input.centre_point, m.input.circle_point, m.output.centre_point, m.output.circle_point})
      s << ',' << z.real() << ',' << z.imag();
    return s.str();
  }
  const char *header = "ground,input,coupler,output,perimeter,grashof,mu_min_positions_deg,mu_max_positions_deg,"
                       "mu_min_motion_deg,mu_max_motion_deg,input_sweep_deg,toggle_margin_mu_deg,toggle_margin_input_deg,position_error,angle_error_rad,defect,"
                       "Ax,Ay,Bx,By,Dx,Dy,Cx,Cy";

  // Writes through a temporary name: a file appears complete or not at all.
  void write_file(const std::filesystem::path &path, const std::string &text)
  {
    const auto tmp = path.string() + ".tmp";
    {
      std::ofstream out(tmp);
      out << text;
      if (!out)
        throw std::runtime_error("cannot write '" + tmp + "'");
    }
    std::filesystem::rename(tmp, path);
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      if (argc < 2 || argc > 3)
        throw InputError("usage: burmester_synthesis CASE [OUTPUT_DIR]");
      const Case        c   = read_case(argv[1]);
      const std::string out = argc == 3 ? argv[2] : "results/burmester";

      const auto curves = burmester_curves(c.positions, c.curve_samples);
      if (curves.empty())
        throw InputError(std::string(argv[1]) + ": these positions admit no real dyad");
      double worst_residual = 0;
      for (const auto &d : curves)
        worst_residual = std::max(worst_residual, dyad_residual(c.positions, d));

      // Pair a subsample of the dyads whose link and coupler side fit the size bound.
      std::vector<Dyad> usable;
      for (const auto &d : curves)
        if (std::abs(d.W) <= c.criteria.max_link_length && std::abs(d.W) >= c.criteria.min_link_length &&
            std::abs(d.Z) <= 2 * c.criteria.max_link_length)
          usable.push_back(d);
      const std::size_t stride = std::max<std::size_t>(1, usable.size() / c.pair_dyads);
      std::vector<Dyad> sample;
      for (std::size_t i = 0; i < usable.size(); i += stride)
        sample.push_back(usable[i]);

      std::vector<CandidateMechanism> all;
      for (std::size_t i = 0; i < sample.size(); ++i)
        for (std::size_t j = 0; j < sample.size(); ++j)
          if (i != j && std::abs(sample[i].centre_point - sample[j].centre_point) > 1e-6)
            all.push_back(analyse_candidate(c.positions, sample[i], sample[j]));

      std::vector<const CandidateMechanism *> paper_kept, ranked;
      for (const auto &m : all)
        {
          if (meets_paper_criteria(m, c.criteria))
            paper_kept.push_back(&m);
          if (meets_all_criteria(m, c.criteria))
            ranked.push_back(&m);
        }
      auto better = [](const CandidateMechanism *a, const CandidateMechanism *b) {
        const bool da = a->grashof.class_ == four_bar::GrashofClass::double_crank;
        const bool db = b->grashof.class_ == four_bar::GrashofClass::double_crank;
        return da != db ? da : a->perimeter < b->perimeter;
      };
      std::sort(ranked.begin(), ranked.end(), better);
      std::sort(paper_kept.begin(), paper_kept.end(), better);

      const PivotFit pivot = best_single_pivot(c.positions);
      std::map<std::string, int> defects;
      for (const auto *m : paper_kept)
        ++defects[m->defect.empty() ? "none" : m->defect.substr(0, m->defect.find(':'))];

      std::cout << "Burmester synthesis: " << curves.size() << " dyads on the curves (" << c.curve_samples
                << " beta2 samples), worst loop-equation residual " << std::scientific << std::setprecision(2)
                << worst_residual << "\n"
                << sample.size() << " dyads paired: " << all.size() << " candidate four-bars (both links tried as input)\n"
                << paper_kept.size() << " meet the paper's criteria (Grashof, " << std::fixed << std::setprecision(0)
                << deg(c.criteria.mu_low) << "-" << deg(c.criteria.mu_high)
                << " deg transmission at the four positions, links " << std::setprecision(3) << c.criteria.min_link_length << " to "
                << c.criteria.max_link_length
                << "); their defect verdicts:";
      for (const auto &[name, count] : defects)
        std::cout << " " << name << " " << count << ";";
      std::cout << "\n";
      std::printf("Nearest pure rotation: one pivot at (%.4f, %.4f), radius %.4f, carries the coupler through "
                  "the positions within %.2e (orientations exact)\n",
                  pivot.centre.real(), pivot.centre.imag(), pivot.radius, pivot.position_error);
      int double_cranks = 0;
      for (const auto *m : paper_kept)
        double_cranks += m->grashof.class_ == four_bar::GrashofClass::double_crank;
      std::cout << "Grashof double cranks among them: " << double_cranks << "\n";

      std::ostringstream table;
      table << "rank," << header << "\n";
      if (ranked.empty())
        {
          std::cout << "NO candidate meets every criterion (Grashof, transmission angle over the whole "
                       "motion, no order/branch/circuit defect).\n";
          // The defect-free mechanisms with the widest transmission band, whatever their class.
          std::vector<const CandidateMechanism *> clean;
          std::map<std::string, int>              verdicts; // of every candidate within the link bounds
          for (const auto &m : all)
            if (m.lengths.longest() <= c.criteria.max_link_length &&
                std::min({m.lengths.ground, m.lengths.crank, m.lengths.coupler, m.lengths.rocker}) >=
                  c.criteria.min_link_length)
              {
                ++verdicts[m.defect.empty() ? "none" : m.defect.substr(0, m.defect.find(':'))];
                if (m.defect_free)
                  clean.push_back(&m);
              }
          std::sort(clean.begin(), clean.end(), [](auto *a, auto *b) {
            return a->toggle_margin_transmission > b->toggle_margin_transmission;
          });
          clean.resize(std::min<std::size_t>(clean.size(), 10));
          ranked = clean;
          std::cout << "Defect verdicts of the candidates with links within the bounds, whatever their class:";
          for (const auto &[name, count] : verdicts)
            std::cout << " " << name << " " << count << ";";
          std::cout << (clean.empty() ? "\nNo defect-free four-bar at all within the link bounds: the single pivot "
                                        "above is the answer to these positions.\n"
                                      : "\nBest trade-offs (defect-free, largest distance to a toggle):\n");
        }
      if (!ranked.empty())
        std::cout << "rank  ground  input  coupler  output  perimeter  class           mu(motion) deg  sweep deg  "
                   "toggle margin: mu, input deg  pos.err   defect\n";
      for (std::size_t k = 0; k < ranked.size() && k < 15; ++k)
        {
          const auto &m = *ranked[k];
          std::printf("%4zu  %6.4f %6.4f  %6.4f  %6.4f  %9.4f  %-15s %6.1f-%6.1f  %9.1f  %13.2f %13.2f  %8.1e  %s\n",
                      k + 1, m.lengths.ground, m.lengths.crank, m.lengths.coupler, m.lengths.rocker, m.perimeter,
                      four_bar::to_string(m.grashof.class_).c_str(), deg(m.mu_min), deg(m.mu_max),
                      deg(m.input_sweep), deg(m.toggle_margin_transmission), deg(m.toggle_margin_input),
                      m.position_error, m.defect.empty() ? "none" : m.defect.c_str());
        }
      for (std::size_t k = 0; k < ranked.size(); ++k)
        table << k + 1 << ',' << row(*ranked[k]) << "\n";
      if (!paper_kept.empty())
        {
          std::cout << "\nThe paper's choice (shortest Grashof double crank by its criteria):\n";
          const CandidateMechanism *pick = nullptr;
          for (const auto *m : paper_kept)
            if (m->grashof.class_ == four_bar::GrashofClass::double_crank)
              {
                pick = m;
                break;
              }
          if (!pick)
            std::cout << "  none of the kept candidates is a double crank\n";
          else
            std::printf("  ground %.4f input %.4f coupler %.4f output %.4f; transmission %.1f-%.1f deg over the motion; defect: %s\n",
                        pick->lengths.ground, pick->lengths.crank, pick->lengths.coupler, pick->lengths.rocker,
                        deg(pick->mu_min), deg(pick->mu_max), pick->defect.empty() ? "none" : pick->defect.c_str());
        }

      std::ostringstream curve_csv, all_csv;
      curve_csv << "beta2_deg,Mx,My,Kx,Ky,residual\n" << std::setprecision(10);
      for (const auto &d : curves)
        curve_csv << deg(d.beta2) << ',' << d.centre_point.real() << ',' << d.centre_point.imag() << ','
                  << d.circle_point.real() << ',' << d.circle_point.imag() << ',' << dyad_residual(c.positions, d) << "\n";
      all_csv << "paper_criteria,all_criteria," << header << "\n";
      for (const auto &m : all)
        all_csv << meets_paper_criteria(m, c.criteria) << ',' << meets_all_criteria(m, c.criteria) << ',' << row(m) << "\n";
      std::ostringstream positions_csv;
      positions_csv << "x,y,angle_deg\n" << std::setprecision(17);
      for (const auto &p : c.positions)
        positions_csv << p.x << ',' << p.y << ',' << deg(p.angle) << "\n";
      // The single revolute joint at the pole (the practical answer when the curves collapse): per
      // position its spar point, R_1 turned about the pivot, and how far that misses R_j. The
      // compliant version (cases/morphing_wing/compliant_pivot.prm) starts from this file.
      std::ostringstream pivot_csv;
      pivot_csv << "position,pivot_x,pivot_y,radius,rotation_deg,rigid_x,rigid_y,target_x,target_y,rigid_miss\n"
                << std::setprecision(10);
      for (std::size_t j = 0; j < c.positions.size(); ++j)
        {
          const auto   &p0  = c.positions.front(), &pj = c.positions[j];
          const double  turn = pj.angle - p0.angle;
          const Complex rigid =
            pivot.centre + (Complex(p0.x, p0.y) - pivot.centre) * std::polar(1.0, turn);
          pivot_csv << j + 1 << ',' << pivot.centre.real() << ',' << pivot.centre.imag() << ',' << pivot.radius << ','
                    << deg(turn) << ',' << rigid.real() << ',' << rigid.imag() << ',' << pj.x << ',' << pj.y << ','
                    << std::abs(rigid - Complex(pj.x, pj.y)) << "\n";
        }
      std::filesystem::create_directories(out);
      write_file(std::filesystem::path(out) / "single_pivot.csv", pivot_csv.str());
      write_file(std::filesystem::path(out) / "burmester_curves.csv", curve_csv.str());
      write_file(std::filesystem::path(out) / "candidates.csv", all_csv.str());
      write_file(std::filesystem::path(out) / "mechanisms.csv", table.str());
      write_file(std::filesystem::path(out) / "positions.csv", positions_csv.str());
      std::cout << "\nWrote " << out << "/{burmester_curves,candidates,mechanisms,positions,single_pivot}.csv\n";
      return 0;
    }
  catch (const InputError &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 1;
    }
}
