// fatigue_life: fatigue life of named hot spots from the CSV history of one duty cycle.
// Rainflow table, Miner damage per hot spot, life in repeats of the duty cycle with its band, the
// critical location, and (with --run-out) what a test that survived N repeats implies.
#include <fatigue/history_csv.h>
#include <fatigue/hot_spot_assessment.h>
#include <text/text_utilities.h>
#include <fatigue/printed_tpu.h>
#include <fatigue/run_out.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  using namespace fatigue;

  const char *usage_text = R"(usage: fatigue_life [options] HISTORY.csv

HISTORY.csv: a header 'time,<hot spot 1>,<hot spot 2>,...', then one row per sample of ONE duty
cycle; the first column is time or step (strictly increasing), each further column the history of
one hot spot: maximum principal strain (fraction, not percent) or maximum principal stress (MPa).

options:
  --quantity strain|stress   what the hot-spot columns hold (default strain)
  --columns A,B,...          hot spots to assess (default: every column but the first)
  --correction NAME          mean correction: elastomer-walker (strain default), swt (stress
                             default), goodman (stress), none
  --walker-exponent G        gamma of elastomer-walker (default 0.5)
  --ultimate-strength S      sigma_u of goodman, MPa (default 22, printed TPU in plane, lower end)
  --curve MEMBER=A,N,K[,E]   replace band member low|nominal|high of the built-in printed TPU
                             curve by N(a) = N (a/A)^-K, endurance amplitude E (default 0)
  --single-pass              count the history once (ASTM E1049-85 5.4.4, residue as half cycles)
                             instead of as a repeating duty cycle (5.4.5, the default)
  --gate G                   hysteresis filter: drop excursions of range <= G (default 0)
  --scale F                  multiply every history value by F first (0.01: percent -> fraction,
                             1e-6: Pa -> MPa)
  --run-out N                the duty cycle survived N repeats without failure: check each curve and
                             report the life again with contradicted curves lifted to the run-out
  --target N                 life target in repeats (default 1e6)
  --table-rows N             rainflow table rows printed per hot spot, largest ranges first
                             (default 30, 0: all; the damage sums always use every cycle)
  --summary-csv PATH         write the counted cycles and curves for postproc/fatigue_life_chart.py
  -h, --help                 this text

exit status: 0 success, 1 bad input (file, column, value), 2 bad command line
)";

  struct UsageError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  struct Options
  {
    std::string                path;
    Quantity                   quantity = Quantity::strain;
    std::vector<std::string>   columns;
    std::optional<std::string> correction;
    double                     walker_exponent   = 0.5;
    double                     ultimate_strength = printed_tpu::default_ultimate_strength;
    std::vector<std::string>   curve_overrides;
    HistoryKind                kind  = HistoryKind::repeating;
    double                     gate  = 0.0;
    double                     scale = 1.0;
    std::optional<double>      run_out;
    double                     target     = 1.0e6;
    std::size_t                table_rows = 30;
    std::optional<std::string> summary_csv;
  };

  using compliant::text::split;

  double
  parse_double(const std::string &option, const std::string &text)
  {
    char        *end   = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
      throw UsageError("option " + option + ": '" + text + "' is not a finite number");
    return value;
  }

  Options
  parse_command_line(const int argc, char **argv)
  {
    Options options;
    auto    value_of = [&](int &i) -> std::string {
      if (i + 1 >= argc)
        throw UsageError(std::string("option ") + argv[i] + " needs a value");
      return argv[++i];
    };
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help")
          {
            std::cout << usage_text;
            std::exit(0);
          }
        else if (arg == "--quantity")
          {
            const std::string name = value_of(i);
            if (name != "strain" && name != "stress")
              throw UsageError("option --quantity: expected 'strain' or 'stress', got '" + name +
                               "'");
            options.quantity = parse_quantity(name);
          }
        else if (arg == "--columns")
          options.columns = split(value_of(i), ',');
        else if (arg == "--correction")
          options.correction = value_of(i);
        else if (arg == "--walker-exponent")
          options.walker_exponent = parse_double(arg, value_of(i));
        else if (arg == "--ultimate-strength")
          options.ultimate_strength = parse_double(arg, value_of(i));
        else if (arg == "--curve")
          options.curve_overrides.push_back(value_of(i));
        else if (arg == "--single-pass")
          options.kind = HistoryKind::single_pass;
        else if (arg == "--gate")
          options.gate = parse_double(arg, value_of(i));
        else if (arg == "--scale")
          options.scale = parse_double(arg, value_of(i));
        else if (arg == "--run-out")
          options.run_out = parse_double(arg, value_of(i));
        else if (arg == "--target")
          options.target = parse_double(arg, value_of(i));
        else if (arg == "--table-rows")
          {
            const double rows = parse_double(arg, value_of(i));
            if (rows < 0.0 || rows != std::floor(rows))
              throw UsageError("option --table-rows: expected a whole number >= 0");
            options.table_rows = static_cast<std::size_t>(rows);
          }
        else if (arg == "--summary-csv")
          options.summary_csv = value_of(i);
        else if (!arg.empty() && arg[0] == '-')
          throw UsageError("unknown option '" + arg + "'");
        else if (options.path.empty())
          options.path = arg;
        else
          throw UsageError("more than one history file given ('" + options.path + "' and '" + arg +
                           "')");
      }
    if (options.path.empty())
      throw UsageError("no history file given");
    if (!(options.target > 0.0))
      throw UsageError("option --target: expected a positive number of repeats");
    if (options.run_out && !(*options.run_out > 0.0))
      throw UsageError("option --run-out: expected a positive number of repeats");
    if (!(options.scale > 0.0))
      throw UsageError("option --scale: expected a positive factor");
    return options;
  }

  void
  apply_curve_override(FatigueModel &model, const std::string &spec)
  {
    const auto equals = spec.find('=');
    if (equals == std::string::npos)
      throw UsageError("option --curve: expected MEMBER=A,N,K[,E], got '" + spec + "'");
    const std::string member = spec.substr(0, equals);
    std::size_t       index;
    if (member == "low")
      index = low_life;
    else if (member == "nominal")
      index = nominal_life;
    else if (member == "high")
      index = high_life;
    else
      throw UsageError("option --curve: band member must be low, nominal or high, got '" + member +
                       "'");
    const std::vector<std::string> values = split(spec.substr(equals + 1), ',');
    if (values.size() != 3 && values.size() != 4)
      throw UsageError("option --curve: expected 3 or 4 numbers A,N,K[,E] after '" + member +
                       "=', got '" + spec.substr(equals + 1) + "'");
    LifeCurve curve;
    curve.name                = model.name + "/" + member + " (user)";
    curve.reference_amplitude = parse_double("--curve", values[0]);
    curve.reference_cycles    = parse_double("--curve", values[1]);
    curve.exponent            = parse_double("--curve", values[2]);
    curve.endurance_amplitude = values.size() == 4 ? parse_double("--curve", values[3]) : 0.0;
    curve.source              = "given on the command line";
    curve.check();
    model.curves[index] = curve;
  }

  FatigueModel
  build_model(const Options &options)
  {
    FatigueModel model;
    if (options.quantity == Quantity::strain)
      {
        MeanCorrectionSettings correction;
        const std::string      name = options.correction.value_or("elastomer-walker");
        correction.kind             = parse_mean_correction(name);
        if (correction.kind != MeanCorrection::elastomer_walker &&
            correction.kind != MeanCorrection::none)
          throw UsageError(
              "option --correction: '" + name +
              "' is stress based; with --quantity strain use elastomer-walker or none");
        correction.walker_exponent = options.walker_exponent;
        model                      = printed_tpu::strain_model(correction);
      }
    else
      {
        MeanCorrectionSettings correction;
        const std::string      name = options.correction.value_or("swt");
        correction.kind             = parse_mean_correction(name);
        if (correction.kind == MeanCorrection::elastomer_walker)
          throw UsageError(
              "option --correction: 'elastomer-walker' is strain based; with --quantity "
              "stress use swt, goodman or none");
        correction.ultimate_strength = options.ultimate_strength;
        model                        = printed_tpu::stress_model(correction);
      }
    for (const std::string &spec : options.curve_overrides)
      apply_curve_override(model, spec);
    model.check();
    return model;
  }

  std::string
  fmt(const double value, const int precision = 4)
  {
    if (std::isinf(value))
      return value > 0 ? "inf" : "-inf";
    std::ostringstream out;
    const double       magnitude = std::abs(value);
    if (value != 0.0 && (magnitude >= 1e5 || magnitude < 1e-3))
      out << std::scientific << std::setprecision(precision - 1) << value;
    else
      out << std::setprecision(precision) << value;
    return out.str();
  }

  void
  print_model(const FatigueModel &model)
  {
    std::cout << "model: " << model.name << " (quantity " << to_string(model.quantity) << ", unit "
              << (model.unit.empty() ? "dimensionless" : model.unit) << ")\n"
              << "  " << model.assumption << "\n"
              << "  mean correction: " << describe(model.correction) << "\n";
    for (std::size_t m = 0; m < n_band_members; ++m)
      {
        const LifeCurve &c = model.curves[m];
        std::cout << "  " << std::left << std::setw(8) << band_member_name(m) << std::right
                  << "N = " << fmt(c.reference_cycles) << " (a / " << fmt(c.reference_amplitude)
                  << ")^-" << fmt(c.exponent);
        if (c.endurance_amplitude > 0.0)
          std::cout << ", no damage below " << fmt(c.endurance_amplitude);
        std::cout << "   [" << c.source << "]\n";
      }
  }

  void
  print_hot_spot(const HotSpotResult &h, const FatigueModel &model, const std::size_t max_rows)
  {
    std::cout << "\nhot spot '" << h.name << "': " << h.cycles.size() << " counted ranges, "
              << fmt(total_count(h.cycles)) << " cycles per duty cycle\n";
    std::cout << "  " << std::setw(12) << "range" << std::setw(12) << "mean" << std::setw(8)
              << "count" << std::setw(12) << "a_eq" << std::setw(12) << "N_nominal" << std::setw(12)
              << "D_nominal"
              << "\n";
    const std::vector<RainflowTableRow> rows = tabulate(h.cycles);
    for (std::size_t r = 0; r < rows.size() && (max_rows == 0 || r < max_rows); ++r)
      {
        const RainflowTableRow &row     = rows[r];
        const double            a       = equivalent_amplitude(row.mean + 0.5 * row.range,
                                                               row.mean - 0.5 * row.range, model.correction);
        const LifeCurve        &nominal = model.curves[nominal_life];
        std::cout << "  " << std::setw(12) << fmt(row.range) << std::setw(12) << fmt(row.mean)
                  << std::setw(8) << fmt(row.count) << std::setw(12) << fmt(a) << std::setw(12)
                  << fmt(nominal.cycles_to_failure(a)) << std::setw(12)
                  << fmt(row.count * nominal.damage_per_cycle(a)) << "\n";
      }
    if (max_rows > 0 && rows.size() > max_rows)
      std::cout << "  ... " << rows.size() - max_rows
                << " smaller ranges not shown (--table-rows 0)\n";
    std::cout << "  damage per duty cycle (low / nominal / high curve): "
              << fmt(h.damage_per_repeat[low_life]) << " / "
              << fmt(h.damage_per_repeat[nominal_life]) << " / "
              << fmt(h.damage_per_repeat[high_life]) << "\n";
    const LifeBand life = h.life();
    std::cout << "  life [duty cycles]: nominal " << fmt(life.nominal) << ", band " << fmt(life.low)
              << " .. " << fmt(life.high) << "\n";
  }

  void
  print_summary(const FatigueAssessment &assessment, const double target, const std::string &label)
  {
    const LifeBand life = assessment.life();
    std::cout << "\n"
              << label << "\n"
              << "  critical location: '" << assessment.hot_spots[assessment.critical].name << "'";
    if (!assessment.critical_location_is_robust())
      {
        std::cout << " (nominal curve; ";
        for (std::size_t m = 0; m < n_band_members; ++m)
          std::cout << band_member_name(m) << ": '"
                    << assessment.hot_spots[assessment.critical_per_member[m]].name << "'"
                    << (m + 1 < n_band_members ? ", " : ")");
      }
    std::cout << "\n  predicted life [duty cycles]: nominal " << fmt(life.nominal) << ", band "
              << fmt(life.low) << " .. " << fmt(life.high) << "\n"
              << "  target " << fmt(target) << ": "
              << (life.low >= target ? "met by the whole band"
                  : life.nominal >= target
                      ? "met by the nominal curve, not by the low end of the band"
                  : life.high >= target ? "met only by the high end of the band"
                                        : "not met anywhere in the band")
              << "\n";
  }

  void
  print_run_out(const std::array<RunOutImplication, n_band_members> &implications,
                const FatigueModel &model, const double target)
  {
    std::cout << "\nrun-out: the duty cycle survived " << fmt(implications[0].survived)
              << " repeats without failure (a lower bound on life, not a failure)\n";
    for (std::size_t m = 0; m < n_band_members; ++m)
      {
        const RunOutImplication &r = implications[m];
        std::cout << "  " << std::left << std::setw(8) << band_member_name(m) << std::right
                  << "predicts " << fmt(r.predicted)
                  << " repeats: " << (r.consistent ? "consistent" : "CONTRADICTED by the run-out")
                  << "\n";
        if (r.lower_bound)
          std::cout << "           implies a_ref >= " << fmt(r.lower_bound->reference_amplitude)
                    << " at N = " << fmt(r.curve.reference_cycles)
                    << " for k = " << fmt(r.curve.exponent) << " (curve has "
                    << fmt(r.curve.reference_amplitude)
                    << "); with this slope, equivalent amplitudes up to "
                    << fmt(r.lower_bound->amplitude_at(target))
                    << (model.unit.empty() ? "" : " " + model.unit) << " survive " << fmt(target)
                    << " cycles\n";
        else
          std::cout << "           the tested loading does no damage under this curve: no bound\n";
      }
  }

  void
  write_summary_csv(
      const std::string &path, const FatigueAssessment &assessment,
      const std::optional<FatigueAssessment>                             &constrained,
      const std::optional<std::array<RunOutImplication, n_band_members>> &implications)
  {
    std::ofstream out(path);
    if (!out)
      throw std::invalid_argument("file '" + path +
                                  "': cannot be opened for writing (--summary-csv)");
    out << std::setprecision(10);
    const FatigueModel &model = assessment.model;
    out << "# fatigue_life summary\n# quantity," << to_string(model.quantity) << "," << model.unit
        << "\n# model," << model.name << "\n# critical,"
        << assessment.hot_spots[assessment.critical].name << "\n";
    for (std::size_t m = 0; m < n_band_members; ++m)
      {
        const LifeCurve &c = model.curves[m];
        out << "# curve," << band_member_name(m) << "," << c.reference_amplitude << ","
            << c.reference_cycles << "," << c.exponent << "," << c.endurance_amplitude << "\n";
      }
    if (constrained)
      for (std::size_t m = 0; m < n_band_members; ++m)
        {
          const LifeCurve &c = constrained->model.curves[m];
          out << "# constrained_curve," << band_member_name(m) << "," << c.reference_amplitude
              << "," << c.reference_cycles << "," << c.exponent << "," << c.endurance_amplitude
              << "\n";
        }
    if (implications)
      {
        // The damage-equivalent constant amplitude of the critical hot spot under the nominal
        // curve: one cycle of it per duty cycle does the same damage; it places the run-out on the
        // chart.
        const LifeCurve &nominal = model.curves[nominal_life];
        const double d = assessment.hot_spots[assessment.critical].damage_per_repeat[nominal_life];
        const double a_equivalent =
            d > 0.0 ? nominal.reference_amplitude *
                          std::pow(d * nominal.reference_cycles, 1.0 / nominal.exponent)
                    : 0.0;
        out << "# run_out," << (*implications)[0].survived << "," << a_equivalent << "\n";
      }
    out << "hot_spot,range,mean,count,equivalent_amplitude,cycles_low,cycles_nominal,cycles_high\n";
    for (const HotSpotResult &h : assessment.hot_spots)
      for (const RainflowTableRow &row : tabulate(h.cycles))
        {
          const double a = equivalent_amplitude(row.mean + 0.5 * row.range,
                                                row.mean - 0.5 * row.range, model.correction);
          out << h.name << "," << row.range << "," << row.mean << "," << row.count << "," << a;
          for (const LifeCurve &c : model.curves)
            out << "," << c.cycles_to_failure(a);
          out << "\n";
        }
  }

  int
  run(const Options &options)
  {
    const FatigueModel model = build_model(options);
    HistoryTable       table = read_history_csv(options.path);
    if (!options.columns.empty())
      table = select_columns(table, options.columns);
    for (HotSpotHistory &h : table.hot_spots)
      for (double &v : h.values)
        v *= options.scale;
    if (options.quantity == Quantity::strain)
      for (const HotSpotHistory &h : table.hot_spots)
        for (const double v : h.values)
          if (std::abs(v) > 2.0)
            {
              std::cerr << "fatigue_life: warning: column '" << h.name << "' reaches " << v
                        << "; strains are read as fractions (use --scale 0.01 for percent)\n";
              break;
            }

    CountingSettings counting;
    counting.kind                      = options.kind;
    counting.gate                      = options.gate;
    const FatigueAssessment assessment = assess_fatigue(table.hot_spots, model, counting);

    std::cout << "fatigue_life: " << options.path << " (" << table.steps.size() << " samples of '"
              << table.step_column << "', " << table.hot_spots.size() << " hot spot(s))\n"
              << "counting: rainflow, ASTM E1049-85 "
              << (options.kind == HistoryKind::repeating
                      ? "5.4.5 (the history is one period of a repeating duty cycle)"
                      : "5.4.4 (single pass, residue as half cycles)")
              << (options.gate > 0.0 ? ", gate " + fmt(options.gate) : std::string()) << "\n"
              << "damage: Palmgren-Miner, failure at D = 1; life in repeats of the duty cycle\n";
    print_model(model);
    for (const HotSpotResult &h : assessment.hot_spots)
      print_hot_spot(h, model, options.table_rows);
    print_summary(assessment, options.target, "result:");

    std::optional<FatigueAssessment>                             constrained;
    std::optional<std::array<RunOutImplication, n_band_members>> implications;
    if (options.run_out)
      {
        implications = check_against_run_out(model, assessment.spectra(), *options.run_out);
        print_run_out(*implications, model, options.target);
        constrained =
            assess_fatigue(table.hot_spots, constrained_by_run_out(model, *implications), counting);
        print_summary(*constrained, options.target,
                      "result with contradicted curves lifted to the run-out (lower bounds):");
      }
    if (options.summary_csv)
      write_summary_csv(*options.summary_csv, assessment, constrained, implications);
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  Options options;
  try
    {
      options = parse_command_line(argc, argv);
    }
  catch (const UsageError &e)
    {
      std::cerr << "fatigue_life: " << e.what() << "\n(run fatigue_life --help for the usage)\n";
      return 2;
    }
  try
    {
      return run(options);
    }
  catch (const UsageError &e)
    {
      std::cerr << "fatigue_life: " << e.what() << "\n(run fatigue_life --help for the usage)\n";
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "fatigue_life: error: " << e.what() << "\n";
      return 1;
    }
}
