#include "output/picture_sampling.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include "elasticity/linear_elastic_problem.h"
#include "finite_strain/finite_strain_problem.h"

#include <algorithm>
#include <cmath>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // Points of a reference cell cut s times per edge, and the sub-cells as corner lists.
    template <int d>
    struct Grid
    {
      std::vector<Point<d>>                  points;
      std::vector<std::vector<unsigned int>> cells;
    };

    template <int d>
    Grid<d> make_grid(const bool simplex, const unsigned int s)
    {
      Grid<d> grid;
      if constexpr (d == 1)
        {
          for (unsigned int i = 0; i <= s; ++i)
            grid.points.push_back(Point<d>(double(i) / s));
          for (unsigned int i = 0; i < s; ++i)
            grid.cells.push_back({i, i + 1});
          return grid;
        }
      if constexpr (d == 2)
        {
          // index[i][j] of the point (i/s, j/s); on a triangle only i + j <= s exist.
          std::vector<std::vector<unsigned int>> index(s + 1, std::vector<unsigned int>(s + 1, 0));
          for (unsigned int j = 0; j <= s; ++j)
            for (unsigned int i = 0; i <= s; ++i)
              if (!simplex || i + j <= s)
                {
                  index[i][j] = grid.points.size();
                  grid.points.emplace_back(double(i) / s, double(j) / s);
                }
          for (unsigned int j = 0; j < s; ++j)
            for (unsigned int i = 0; i < s; ++i)
              if (!simplex)
                grid.cells.push_back({index[i][j], index[i + 1][j], index[i + 1][j + 1], index[i][j + 1]});
              else if (i + j < s)
                {
                  grid.cells.push_back({index[i][j], index[i + 1][j], index[i][j + 1]});
                  if (i + j + 1 < s)
                    grid.cells.push_back({index[i + 1][j], index[i + 1][j + 1], index[i][j + 1]});
                }
        }
      return grid;
    }

    template <int dim, class Values>
    std::vector<PictureCorner> corners(const Values &fe_values, const PETScWrappers::MPI::Vector &ghosted,
                                       const Material &material, const PictureValue<dim> &value,
                                       const bool mixed)
    {
      const unsigned int          n = fe_values.n_quadrature_points;
      std::vector<Tensor<1, dim>> u(n);
      std::vector<Tensor<2, dim>> grad(n);
      std::vector<double>         pressure(n, 0.0);
      const FEValuesExtractors::Vector displacement(0);
      fe_values[displacement].get_function_values(ghosted, u);
      fe_values[displacement].get_function_gradients(ghosted, grad);
      if (mixed)
        fe_values[FEValuesExtractors::Scalar(dim)].get_function_values(ghosted, pressure);
      std::vector<PictureCorner> out(n);
      for (unsigned int q = 0; q < n; ++q)
        {
          for (unsigned int d = 0; d < dim; ++d)
            out[q].x[d] = fe_values.quadrature_point(q)[d], out[q].u[d] = u[q][d];
          out[q].value = value(u[q], grad[q], pressure[q], material);
        }
      return out;
    }

    // Corners counter-clockwise seen from outside: against the face's outward normal.
    void orient(std::vector<PictureCorner> &polygon, const Tensor<1, 3> &outward)
    {
      Tensor<1, 3> n;
      for (std::size_t k = 0; k < polygon.size(); ++k)
        {
          const auto &a = polygon[k].x, &b = polygon[(k + 1) % polygon.size()].x;
          n[0] += (a[1] - b[1]) * (a[2] + b[2]);
          n[1] += (a[2] - b[2]) * (a[0] + b[0]);
          n[2] += (a[0] - b[0]) * (a[1] + b[1]);
        }
      if (n * outward < 0)
        std::reverse(polygon.begin(), polygon.end());
    }

    // Sub-cells per edge: twice the degree in 2D, where the colour bands run through the few
    // cells of a flexure's thickness; the degree in 3D (the surface is seen from afar); fewer on
    // large meshes (about 2e4 polygons at most).
    template <int dim>
    unsigned int subdivisions(const Discretization<dim> &discretization)
    {
      const double cells = discretization.triangulation.n_global_active_cells();
      const double faces = dim == 2 ? cells : 6 * std::pow(cells, 2.0 / 3.0);
      const double most  = std::sqrt(2e4 / std::max(faces, 1.0));
      return std::max(1u, std::min<unsigned int>((dim == 2 ? 2 : 1) * discretization.fe->degree, most));
    }

    // Every rank's vector on rank 0 (empty elsewhere). Plain MPI_Gatherv: Utilities::MPI::gather
    // serializes and compresses, which cost more than drawing the picture.
    std::vector<std::vector<double>> gather_doubles(const std::vector<double> &mine, MPI_Comm communicator)
    {
      const int  size = Utilities::MPI::n_mpi_processes(communicator);
      const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
      int        count = static_cast<int>(mine.size());
      std::vector<int> counts(root ? size : 0), offsets(root ? size : 0);
      MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, communicator);
      std::vector<double> all;
      if (root)
        {
          for (int r = 1; r < size; ++r)
            offsets[r] = offsets[r - 1] + counts[r - 1];
          all.resize(offsets.back() + counts.back());
        }
      MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0,
                  communicator);
      std::vector<std::vector<double>> parts;
      for (int r = 0; root && r < size; ++r)
        parts.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
      return parts;
    }
  } // namespace

  template <int dim>
  PictureGeometry sample_picture(const Discretization<dim> &discretization,
                                 const PETScWrappers::MPI::Vector &ghosted, const PictureValue<dim> &value)
  {
    const unsigned int s     = subdivisions(discretization);
    const bool         mixed = discretization.fe->n_components() > dim;
    const bool         simplex = !discretization.triangulation.all_reference_cells_are_hyper_cube();
    const UpdateFlags  flags = update_values | update_gradients | update_quadrature_points;
    PictureGeometry    local;
    local.dim = dim;
    const Grid<dim - 1> face_grid = make_grid<dim - 1>(simplex, s);
    FEFaceValues<dim>   fe_face_values(*discretization.mapping, *discretization.fe,
                                     Quadrature<dim - 1>(face_grid.points), flags | update_normal_vectors);
    const Grid<dim>     cell_grid = make_grid<dim>(simplex, s);
    std::unique_ptr<FEValues<dim>> fe_values;
    if (dim == 2)
      fe_values = std::make_unique<FEValues<dim>>(*discretization.mapping, *discretization.fe,
                                                  Quadrature<dim>(cell_grid.points), flags);
    for (const auto &cell : discretization.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Material &material = discretization.materials.at(cell->material_id());
          if (dim == 2)
            {
              fe_values->reinit(cell);
              const auto c = corners<dim>(*fe_values, ghosted, material, value, mixed);
              for (const auto &sub : cell_grid.cells)
                {
                  std::vector<PictureCorner> polygon;
                  for (const unsigned int i : sub)
                    polygon.push_back(c[i]);
                  local.polygons.push_back(std::move(polygon));
                }
            }
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                fe_face_values.reinit(cell, f);
                const auto c = corners<dim>(fe_face_values, ghosted, material, value, mixed);
                Tensor<1, 3> outward;
                for (unsigned int d = 0; d < dim; ++d)
                  outward[d] = fe_face_values.normal_vector(0)[d];
                for (const auto &sub : face_grid.cells)
                  {
                    std::vector<PictureCorner> polygon;
                    for (const unsigned int i : sub)
                      polygon.push_back(c[i]);
                    if (dim == 2)
                      local.outline.push_back({polygon[0], polygon[1]});
                    else
                      {
                        orient(polygon, outward);
                        local.polygons.push_back(std::move(polygon));
                      }
                  }
              }
        }
    PictureGeometry whole;
    whole.dim = dim;
    for (const auto &part : gather_doubles(flatten(local), discretization.communicator))
      append_flattened(part, whole);
    return whole;
  }

  template <class Problem>
  PictureGeometry sample_von_mises(const Problem &problem)
  {
    constexpr int dim = Problem::dimension;
    return sample_picture<dim>(problem, problem.solution,
                               [&](const Tensor<1, dim> &, const Tensor<2, dim> &grad, const double pressure,
                                   const Material &material) {
                                 double     sigma_zz = 0;
                                 const auto sigma = problem.cauchy_stress(grad, material, pressure, sigma_zz);
                                 return problem.von_mises(sigma, sigma_zz);
                               });
  }

  template PictureGeometry sample_picture(const Discretization<2> &, const PETScWrappers::MPI::Vector &,
                                          const PictureValue<2> &);
  template PictureGeometry sample_picture(const Discretization<3> &, const PETScWrappers::MPI::Vector &,
                                          const PictureValue<3> &);
  template PictureGeometry sample_von_mises(const LinearElasticProblem<2> &);
  template PictureGeometry sample_von_mises(const LinearElasticProblem<3> &);
  template PictureGeometry sample_von_mises(const FiniteStrainProblem<2> &);
  template PictureGeometry sample_von_mises(const FiniteStrainProblem<3> &);
} // namespace compliant
