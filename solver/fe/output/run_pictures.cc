#include "output/run_pictures.h"
#include "output/curve_chart.h"
#include "output/part_picture.h"
#include "output/picture_sampling.h"
#include "output/svg_style.h"

#include <deal.II/base/mpi.h>

#include "elasticity/linear_elastic_problem.h"
#include "finite_strain/finite_strain_problem.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    double quantity(const RunSummary &s, const std::string &name, const double otherwise = 0)
    {
      const auto it = s.quantities.find(name);
      return it == s.quantities.end() ? otherwise : it->second;
    }

    std::string setting(const RunSummary &s, const std::string &key)
    {
      const auto it = s.settings.find(key);
      return it == s.settings.end() ? "" : it->second;
    }

    template <int dim>
    PictureLabels common_labels(const Discretization<dim> &discretization, const RunSummary &s)
    {
      PictureLabels labels;
      const bool    si = discretization.parameters.unit_system == UnitSystem::si;
      labels.length_unit = si ? "m" : "mm";
      labels.value_unit  = si ? "Pa" : "MPa";
      const std::string name = std::filesystem::path(s.case_file).stem().string();
      std::ostringstream subtitle;
      subtitle << name << ": " << setting(s, "analysis") << ", " << setting(s, "model") << ", "
               << short_number(quantity(s, "n_cells"), 9) << " cells, degree " << setting(s, "element_degree")
               << ", " << short_number(quantity(s, "n_dofs"), 9) << " DoFs";
      labels.subtitle = subtitle.str();
      return labels;
    }

    std::string read_file(const std::string &file)
    {
      std::ifstream      in(file);
      std::ostringstream text;
      text << in.rdbuf();
      return text.str();
    }
  } // namespace

  template <class Problem>
  std::vector<Picture> static_pictures(const Problem &problem, const RunSummary &s, const std::string &curve_file)
  {
    constexpr int   dim      = Problem::dimension;
    const auto      geometry = sample_von_mises(problem);
    if (Utilities::MPI::this_mpi_process(problem.communicator) != 0)
      return {};
    PictureLabels labels = common_labels<dim>(problem, s);
    labels.value_name    = "von Mises stress";
    labels.title         = "Deformed part, von Mises stress";
    if (s.quantities.count("max_von_mises") > 0)
      {
        labels.has_peak   = true;
        labels.peak_value = s.quantities.at("max_von_mises");
        const char axis[] = "xyz";
        for (unsigned int d = 0; d < dim; ++d)
          labels.peak_position[d] = quantity(s, std::string("max_von_mises_") + axis[d]);
      }
    if (s.quantities.count("load_factor") > 0)
      labels.title += " at load factor " + short_number(s.quantities.at("load_factor"));
    std::vector<Picture> pictures{{"picture.svg", labels.title, draw_part(geometry, labels)}};
    if (!curve_file.empty())
      {
        const std::string chart = draw_load_displacement(read_file(curve_file), "Load-displacement curve ("
                                                           + std::filesystem::path(s.case_file).stem().string() + ")",
                                                         labels.length_unit);
        if (!chart.empty())
          pictures.push_back({"load_displacement.svg", "Load-displacement curve, one dot per converged step", chart});
      }
    return pictures;
  }

  template <int dim>
  std::vector<Picture> mode_pictures(const Discretization<dim> &discretization,
                                     const std::vector<PETScWrappers::MPI::Vector> &modes, const RunSummary &s)
  {
    std::vector<Picture> pictures;
    const std::size_t    n = std::min<std::size_t>(modes.size(), 24);
    for (std::size_t m = 0; m < n; ++m)
      {
        PETScWrappers::MPI::Vector ghosted(discretization.locally_owned_dofs, discretization.locally_relevant_dofs,
                                           discretization.communicator);
        ghosted                  = modes[m];
        const auto geometry      = sample_picture<dim>(discretization, ghosted,
                                                       [](const Tensor<1, dim> &u, const Tensor<2, dim> &, double,
                                                          const Material &) { return u.norm(); });
        if (Utilities::MPI::this_mpi_process(discretization.communicator) != 0)
          continue;
        PictureLabels labels     = common_labels<dim>(discretization, s);
        const std::string id     = std::to_string(m + 1);
        labels.title             = "Mode " + id + ": " + short_number(quantity(s, "frequency_" + id), 6) + " Hz";
        labels.value_name        = "|u| / largest |u|";
        labels.value_unit        = "";
        labels.mode_amplitude    = 0.1;
        // Relative to the mode's largest displacement: a mode has no amplitude of its own.
        PictureGeometry relative = geometry;
        double          largest  = 0;
        for (const auto &polygon : relative.polygons)
          for (const auto &c : polygon)
            largest = std::max(largest, c.value);
        for (auto &polygon : relative.polygons)
          for (auto &c : polygon)
            c.value = largest > 0 ? c.value / largest : 0;
        pictures.push_back({"mode_" + id + ".svg", labels.title, draw_part(relative, labels)});
      }
    return pictures;
  }

  template std::vector<Picture> static_pictures(const LinearElasticProblem<2> &, const RunSummary &, const std::string &);
  template std::vector<Picture> static_pictures(const LinearElasticProblem<3> &, const RunSummary &, const std::string &);
  template std::vector<Picture> static_pictures(const FiniteStrainProblem<2> &, const RunSummary &, const std::string &);
  template std::vector<Picture> static_pictures(const FiniteStrainProblem<3> &, const RunSummary &, const std::string &);
  template std::vector<Picture> mode_pictures(const Discretization<2> &, const std::vector<PETScWrappers::MPI::Vector> &,
                                              const RunSummary &);
  template std::vector<Picture> mode_pictures(const Discretization<3> &, const std::vector<PETScWrappers::MPI::Vector> &,
                                              const RunSummary &);
} // namespace compliant
