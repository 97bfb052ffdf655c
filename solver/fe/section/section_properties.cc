#include "section/section_properties.h"

#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <stdexcept>

namespace compliant::section
{
  using namespace dealii;

  namespace
  {
    // Points i/m, j/m of the reference cell: vertices, edges and interior (weights unused).
    Quadrature<2> sampling_lattice(const bool simplex, const unsigned int m)
    {
      std::vector<Point<2>> points;
      for (unsigned int i = 0; i <= m; ++i)
        for (unsigned int j = 0; j <= (simplex ? m - i : m); ++j)
          points.emplace_back(double(i) / m, double(j) / m);
      return Quadrature<2>(points, std::vector<double>(points.size(), 1.0));
    }

    struct Moments
    {
      double area = 0, xx = 0, yy = 0, xy = 0;     // int x^2, int y^2, int x y (centroidal)
      double omega_x = 0, omega_y = 0, omega2 = 0; // int omega x, int omega y, int omega^2
      double twist_term = 0;                       // int (x omega_y - y omega_x)
    };

    // Integrals of the warping function about the centroid shifted by (x_s, y_s):
    // omega_S = omega - y_s x + x_s y.
    Moments integrate(const WarpingProblem &problem, const Point<2> &shift)
    {
      FEValues<2> fe_values(*problem.mapping, *problem.fe, *problem.quadrature,
                            update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
      const unsigned int        n_q = fe_values.n_quadrature_points;
      std::vector<double>       omega(n_q);
      std::vector<Tensor<1, 2>> grad(n_q);
      Moments                   m;
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values.get_function_values(problem.warping, omega);
          fe_values.get_function_gradients(problem.warping, grad);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Point<2> p   = problem.relative(fe_values.quadrature_point(q));
              const double   JxW = fe_values.JxW(q);
              const double   w   = omega[q] - shift[1] * p[0] + shift[0] * p[1];
              m.area += JxW;
              m.xx += p[0] * p[0] * JxW;
              m.yy += p[1] * p[1] * JxW;
              m.xy += p[0] * p[1] * JxW;
              m.omega_x += w * p[0] * JxW;
              m.omega_y += w * p[1] * JxW;
              m.omega2 += w * w * JxW;
              m.twist_term += (p[0] * grad[q][1] - p[1] * grad[q][0]) * JxW;
            }
        }
      return m;
    }
  } // namespace

  SectionProperties compute_section_properties(const WarpingProblem &problem)
  {
    SectionProperties s;
    const Moments     about_centroid = integrate(problem, Point<2>());
    s.area                           = about_centroid.area;
    s.centroid                       = problem.centroid;
    s.second_moment_about_x          = about_centroid.yy;
    s.second_moment_about_y          = about_centroid.xx;
    s.product_moment_xy              = about_centroid.xy;
    s.polar_moment                   = about_centroid.xx + about_centroid.yy;
    s.torsion_constant               = s.polar_moment + about_centroid.twist_term;
    s.warping_constant_about_centroid = about_centroid.omega2;

    // int omega_S x = int omega x - y_s I_y + x_s I_xy = 0 and
    // int omega_S y = int omega y - y_s I_xy + x_s I_x = 0, solved for (x_s, y_s).
    const double I_x = about_centroid.yy, I_y = about_centroid.xx, I_xy = about_centroid.xy;
    const double det = I_x * I_y - I_xy * I_xy;
    if (!(det > 0))
      throw std::invalid_argument("the section has no area (degenerate mesh)");
    const Point<2> shift((I_xy * about_centroid.omega_x - I_y * about_centroid.omega_y) / det,
                         (I_x * about_centroid.omega_x - I_xy * about_centroid.omega_y) / det);
    s.shear_centre     = problem.centroid + shift;
    s.warping_constant = integrate(problem, shift).omega2;

    const bool    simplex = problem.triangulation.all_reference_cells_are_simplex();
    FEValues<2>   fe_values(*problem.mapping, *problem.fe,
                          sampling_lattice(simplex, 2 * problem.degree),
                          update_gradients | update_quadrature_points);
    std::vector<Tensor<1, 2>> grad(fe_values.n_quadrature_points);
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values.get_function_gradients(problem.warping, grad);
        for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
          {
            const Point<2> &p   = fe_values.quadrature_point(q);
            const double    tau = shear_per_unit_twist(grad[q], problem.relative(p)).norm();
            if (tau > s.max_shear_factor)
              {
                s.max_shear_factor   = tau;
                s.max_shear_location = p;
              }
          }
      }
    return s;
  }
} // namespace compliant::section
