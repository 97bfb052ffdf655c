#include "section/warping_problem.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include "mesh/curved_manifolds.h"
#include "mesh/curved_simplex_mapping.h"

#include <sstream>
#include <stdexcept>

namespace compliant::section
{
  using namespace dealii;

  WarpingProblem::WarpingProblem(const MeshedGeometry &geometry, const unsigned int degree,
                                 const unsigned int refinements, const std::string &mesh_name)
    : dof_handler(triangulation)
    , degree(degree)
  {
    if (geometry.dimension != 2)
      throw std::invalid_argument("Geometry/Mesh file: '" + mesh_name + "' is " +
                                  std::to_string(geometry.dimension) +
                                  "D; a cross-section must be a 2D (surface) mesh");
    if (degree < 1 || degree > 3)
      throw std::invalid_argument("Discretization/Element degree: expected 1, 2 or 3, got " +
                                  std::to_string(degree));
    GridIn<2> grid_in;
    grid_in.attach_triangulation(triangulation);
    std::istringstream in(geometry.msh_text);
    grid_in.read_msh(in);
    // Circular arcs of the section (fillets, round bars) stay round under refinement and are
    // mapped at the element degree.
    mark_curved_faces(triangulation, geometry.curved.exact);
    attach_curved_manifolds(triangulation, geometry.curved.exact);
    straighten_folding_faces(triangulation, degree);
    triangulation.refine_global(refinements);
    const unsigned int geometry_degree = mapping_degree(geometry.curved, degree);

    if (triangulation.all_reference_cells_are_hyper_cube())
      {
        fe         = std::make_unique<FE_Q<2>>(degree);
        mapping    = std::make_unique<MappingQ<2>>(geometry_degree);
        quadrature = std::make_unique<QGauss<2>>(degree + 1);
      }
    else if (triangulation.all_reference_cells_are_simplex())
      {
        // deal.II 9.4's FE_SimplexP has degrees 1 and 2 only (degree 3 crashes in a release build).
        if (degree > 2)
          throw std::invalid_argument("Discretization/Element degree: triangles allow 1 or 2 "
                                      "(deal.II 9.4), got " + std::to_string(degree) +
                                      "; use quadrilaterals for degree 3");
        fe         = std::make_unique<FE_SimplexP<2>>(degree);
        mapping    = std::make_unique<CurvedSimplexMapping<2>>(geometry_degree);
        quadrature = std::make_unique<QGaussSimplex<2>>(degree + 1);
      }
    else
      throw std::invalid_argument("Geometry/Mesh file: '" + mesh_name +
                                  "' mixes triangles and quadrilaterals; use one cell type");
  }

  void WarpingProblem::compute_area_and_centroid()
  {
    FEValues<2> fe_values(*mapping, *fe, *quadrature, update_quadrature_points | update_JxW_values);
    double      first_moment_x = 0, first_moment_y = 0;
    area = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
          {
            const Point<2> &p = fe_values.quadrature_point(q);
            area += fe_values.JxW(q);
            first_moment_x += p[0] * fe_values.JxW(q);
            first_moment_y += p[1] * fe_values.JxW(q);
          }
      }
    centroid        = Point<2>(first_moment_x / area, first_moment_y / area);
    centroid_offset = centroid;
  }

  void WarpingProblem::solve()
  {
    dof_handler.distribute_dofs(*fe);
    compute_area_and_centroid();

    // The Neumann problem fixes omega up to a constant: pin one value now, shift to zero mean
    // after the solve. The right-hand side integrates to zero for v = 1, so pinning changes nothing
    // else.
    AffineConstraints<double> constraints;
    constraints.add_line(0);
    constraints.close();

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    SparseMatrix<double> matrix(sparsity);
    Vector<double>       rhs(dof_handler.n_dofs());

    // Weak form: int grad omega . grad v dA = int_boundary (y n_x - x n_y) v ds
    //          = int (y dv/dx - x dv/dy) dA   (divergence theorem, div(y, -x) = 0),
    // a domain integral, so inner boundaries (holes) need no separate treatment.
    FEValues<2> fe_values(*mapping, *fe, *quadrature,
                          update_gradients | update_quadrature_points | update_JxW_values);
    const unsigned int                   n = fe->n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell_matrix = 0;
        cell_rhs    = 0;
        fe_values.reinit(cell);
        for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
          {
            const Point<2> p   = relative(fe_values.quadrature_point(q));
            const double   JxW = fe_values.JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              {
                const Tensor<1, 2> grad_i = fe_values.shape_grad(i, q);
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) += grad_i * fe_values.shape_grad(j, q) * JxW;
                cell_rhs(i) += (p[1] * grad_i[0] - p[0] * grad_i[1]) * JxW;
              }
          }
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, matrix, rhs);
      }

    SparseDirectUMFPACK direct;
    direct.initialize(matrix);
    warping = rhs;
    direct.solve(warping);
    constraints.distribute(warping);

    // The shape functions sum to one, so subtracting the mean from every value shifts omega_h.
    const double mean =
      VectorTools::compute_mean_value(*mapping, dof_handler, *quadrature, warping, 0);
    warping.add(-mean);
  }
} // namespace compliant::section
