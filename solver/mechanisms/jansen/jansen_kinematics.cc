// jansen_kinematics: position, velocity and acceleration of the Jansen leg over
// a full crank turn (CSV) and the ground-contact report against the seed paper
// (markdown). See solver/mechanisms/jansen/README.md.
#include <mechanisms/jansen/jansen_crank_turn.h>
#include <mechanisms/jansen/jansen_csv.h>
#include <mechanisms/jansen/jansen_parameter_file.h>
#include <mechanisms/jansen/jansen_report.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>

namespace
{
  using namespace compliant::jansen;

  const char *usage =
    "Usage: jansen_kinematics [options]\n"
    "  --omega <rad/s>     constant crank speed, > 0 counter-clockwise (default 10)\n"
    "  --steps <n>         crank-angle intervals over the turn, >= 1 (default 360)\n"
    "  --out <file.csv>    write foot path, foot velocity/acceleration, link angles,\n"
    "                      rates and joint coordinates for theta2 = 0..360 deg\n"
    "  --report <file.md>  write the ground-contact report beside the paper's numbers\n"
    "  --lengths <file>    leg dimensions ('set EA = 193.96' ...; default: the paper's)\n"
    "  --help              print this text\n";

  struct Options
  {
    double       omega2 = 10.;
    unsigned int steps  = 360;
    std::string  csv_file;
    std::string  report_file;
    std::string  lengths_file;
  };

  double parse_number(const std::string &option, const std::string &text)
  {
    std::size_t used  = 0;
    double      value = 0.;
    try
      {
        value = std::stod(text, &used);
      }
    catch (const std::exception &)
      {
        used = 0;
      }
    if (used == 0 || used != text.size() || !std::isfinite(value))
      throw std::invalid_argument(option + " expects a finite number, got '" + text + "'");
    return value;
  }

  Options parse_options(const int argc, char **argv)
  {
    Options options;
    for (int i = 1; i < argc; ++i)
      {
        const std::string option = argv[i];
        if (option == "--help" || option == "-h")
          {
            std::cout << usage;
            std::exit(0);
          }
        if (i + 1 >= argc)
          throw std::invalid_argument("unknown option or missing value: '" + option + "'");
        const std::string value = argv[++i];
        if (option == "--omega")
          options.omega2 = parse_number(option, value);
        else if (option == "--steps")
          {
            const double steps = parse_number(option, value);
            if (steps < 1. || steps > 1e7 || steps != std::floor(steps))
              throw std::invalid_argument("--steps expects a whole number between 1 and 1e7, got '" +
                                          value + "'");
            options.steps = static_cast<unsigned int>(steps);
          }
        else if (option == "--out")
          options.csv_file = value;
        else if (option == "--report")
          options.report_file = value;
        else if (option == "--lengths")
          options.lengths_file = value;
        else
          throw std::invalid_argument("unknown option '" + option + "'");
      }
    return options;
  }

  // Writes through a temporary file so that a failed run leaves no half file.
  void write_file(const std::string &file_name, const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = file_name + ".tmp";
    {
      std::ofstream out(temporary);
      if (!out)
        throw std::invalid_argument("cannot open '" + file_name + "' for writing");
      write(out);
      if (!out)
        throw std::runtime_error("writing '" + file_name + "' failed");
    }
    if (std::rename(temporary.c_str(), file_name.c_str()) != 0)
      throw std::runtime_error("cannot move '" + temporary + "' to '" + file_name + "'");
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      const Options           options = parse_options(argc, argv);
      const JansenLinkLengths lengths = options.lengths_file.empty() ?
                                          paper_link_lengths() :
                                          read_link_lengths_file(options.lengths_file);

      const GroundContact contact = find_ground_contact(lengths);
      const JansenState   state =
        analyse_state(lengths, contact.lowest.theta2, options.omega2);
      const PlanarVector &v = state.motion.velocities[Joint::H];
      const PlanarVector &a = state.motion.accelerations[Joint::H];
      std::cout << "ground contact (foot lowest): theta2 = " << contact.lowest.theta2 * 180. / M_PI
                << " deg, H = (" << contact.lowest.foot.x << ", " << contact.lowest.foot.y
                << ") mm\n  at omega2 = " << options.omega2 << " rad/s: V_H = (" << v.x << ", "
                << v.y << ") mm/s, a_H = (" << a.x << ", " << a.y << ") mm/s^2\n";

      if (!options.csv_file.empty())
        {
          const auto states = sweep_crank_turn(lengths, options.omega2, options.steps);
          write_file(options.csv_file,
                     [&](std::ostream &out) { write_crank_turn_csv(out, states); });
          std::cout << "wrote " << states.size() << " crank angles to " << options.csv_file
                    << "\n";
        }
      if (!options.report_file.empty())
        {
          ReportSettings settings;
          settings.omega2 = options.omega2;
          write_file(options.report_file,
                     [&](std::ostream &out) { write_report(out, lengths, settings); });
          std::cout << "wrote report to " << options.report_file << "\n";
        }
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << "jansen_kinematics: error: " << e.what() << "\n" << usage;
      return 1;
    }
}
