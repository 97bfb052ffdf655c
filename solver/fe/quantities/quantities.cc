#include "quantities/quantities.h"
#include "quantities/reaction_weights.h"

#include "quantities/named_points.h"
#include "quantities/peak_sampling.h"
#include "quantities/point_location.h"
#include "quantities/point_stress.h"
#include "quantities/region_maxima.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/full_matrix.h>

#include <array>

#include "finite_strain/finite_strain_problem.h"
#include "elasticity/linear_elastic_problem.h"
#include "input/expression.h"
#include "input/spec_list.h"

namespace compliant
{
  using namespace dealii;

  namespace
  {
    const char *axis_name[3] = {"x", "y", "z"};

    template <int dim>
    std::map<std::string, Point<dim>> requested_points(const CaseParameters &p)
    {
      return parse_named_points<dim>(p.points, p.geometry_parameters, "Quantities/Points");
    }

    // Moment points of the Reactions entry; boundaries without one use the origin.
    template <int dim>
    std::map<std::string, Point<3>> reaction_points(const CaseParameters &p)
    {
      std::map<std::string, Point<3>> points;
      for (const auto &item : parse_spec_list(p.reactions, "Quantities/Reactions"))
        {
          Point<3> x;
          if (!item.fields.empty())
            {
              const auto v = parse_numbers(item.fields[0].value, "Quantities/Reactions");
              if (v.size() < dim || v.size() > 3)
                throw std::invalid_argument("Quantities/Reactions: moment point of '" + item.name +
                                            "' needs " + std::to_string(dim) + " coordinates");
              for (unsigned int d = 0; d < v.size(); ++d)
                x[d] = v[d];
            }
          points[item.name] = x;
        }
      return points;
    }

    std::vector<std::string> names_in(const std::string &list)
    {
      std::vector<std::string> names;
      for (const auto &n : split(list, ','))
        if (!n.empty())
          names.push_back(n);
      return names;
    }

    // Value of the solution at a point, found by whichever rank owns the cell around it.
    template <class Problem, int dim = Problem::dimension>
    Tensor<1, dim> point_displacement(const Problem &problem, const Point<dim> &p,
                                      bool &found)
    {
      Tensor<1, dim> value;
      double         owner_count = 0;
      const auto cell_and_point = owned_cell_around(problem.point_mapping(), problem.dof_handler, p);
      if (cell_and_point.first.state() == IteratorState::valid)
        {
          const Quadrature<dim> q(cell_and_point.second);
          FEValues<dim>         fe_values(*problem.mapping, *problem.fe, q, update_values);
          fe_values.reinit(cell_and_point.first);
          std::vector<Tensor<1, dim>> u(1);
          fe_values[FEValuesExtractors::Vector(0)].get_function_values(problem.solution, u);
          value       = u[0];
          owner_count = 1;
        }
      owner_count = Utilities::MPI::sum(owner_count, problem.communicator);
      found       = owner_count > 0;
      value       = Utilities::MPI::sum(value, problem.communicator);
      return found ? value / owner_count : value;
    }

    // Location and component of each locally owned DoF.
    // Support points of the displacement base element (a mixed element's pressure has none).
    template <int dim>
    Quadrature<dim> displacement_support_points(const FiniteElement<dim> &fe)
    {
      return Quadrature<dim>(fe.base_element(0).get_unit_support_points());
    }

    template <int dim>
    struct DofLocation
    {
      unsigned int component;
      Point<dim>   reference; // support point
      Point<dim>   current;   // support point moved by the displacement
    };

    // Component and position of each locally owned displacement DoF.
    template <class Problem, int dim = Problem::dimension>
    std::map<types::global_dof_index, DofLocation<dim>> owned_dof_locations(const Problem &problem)
    {
      std::map<types::global_dof_index, DofLocation<dim>> locations;
      const Quadrature<dim> support = displacement_support_points(*problem.fe);
      FEValues<dim> fe_values(*problem.mapping, *problem.fe, support,
                              update_values | update_quadrature_points);
      std::vector<types::global_dof_index> dofs(problem.fe->n_dofs_per_cell());
      std::vector<Tensor<1, dim>>          u(support.size());
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[FEValuesExtractors::Vector(0)].get_function_values(problem.solution, u);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (problem.locally_owned_dofs.is_element(dofs[i]) &&
                  problem.fe->system_to_component_index(i).first < dim)
                {
                  const unsigned int k = problem.fe->system_to_base_index(i).second;
                  locations[dofs[i]]   = {problem.fe->system_to_component_index(i).first,
                                        fe_values.quadrature_point(k),
                                        fe_values.quadrature_point(k) + u[k]};
                }
          }
      return locations;
    }

    template <int dim>
    using DofLocations = std::map<types::global_dof_index, DofLocation<dim>>;

    // Displacement DoFs on the boundary with this id (a mixed element's pressure has none).
    template <class Problem>
    IndexSet boundary_displacement_dofs(const Problem &problem, const int id)
    {
      const ComponentMask displacement_mask =
        problem.fe->component_mask(FEValuesExtractors::Vector(0));
      return DoFTools::extract_boundary_dofs(problem.dof_handler, displacement_mask,
                                             {static_cast<types::boundary_id>(id)});
    }

    template <class Problem>
    void add_mesh_sizes(const Problem &problem, Quantities &q)
    {
      q["n_dofs"]            = problem.dof_handler.n_dofs();
      q["n_cells"]           = problem.triangulation.n_global_active_cells();
      q["n_ranks"]           = Utilities::MPI::n_mpi_processes(problem.communicator);
    }

    // Displacement at each point of Quantities/Points.
    template <class Problem, int dim = Problem::dimension>
    void add_point_displacements(const Problem &problem, Quantities &q)
    {
      for (const auto &[name, point] : requested_points<dim>(problem.parameters))
        {
          bool       found;
          const auto u = point_displacement(problem, point, found);
          for (unsigned int d = 0; d < dim; ++d)
            q["displacement_" + name + "_" + axis_name[d]] = u[d];
        }
    }

    // A boundary whose reactions are reported, and the point their moment is taken about.
    struct ReactionBoundary
    {
      std::string name;
      int         id;
      Point<3>    moment_point;
    };

    // Every supported boundary: clamped, driven, then the others named in Quantities/Reactions.
    // The moment point is the rotation center for driven rotations, else the one given in
    // Quantities/Reactions, else the origin.
    template <class Problem, int dim = Problem::dimension>
    std::vector<ReactionBoundary> reaction_boundaries(const Problem &problem)
    {
      const auto &p  = problem.parameters;
      const auto &bc = problem.boundary_conditions;
      auto        moment_points = reaction_points<dim>(p);
      std::vector<std::pair<std::string, int>> supported = bc.clamped;
      for (const auto &d : bc.displacements)
        supported.emplace_back(d.boundary, d.boundary_id);
      for (const auto &r : bc.rotations)
        {
          supported.emplace_back(r.boundary, r.boundary_id);
          moment_points[r.boundary] = r.center;
        }
      for (const auto &[name, point] : reaction_points<dim>(p))
        if (std::find_if(supported.begin(), supported.end(),
                         [&](const auto &s) { return s.first == name; }) == supported.end())
          supported.emplace_back(name, problem.geometry.boundary_ids.at(name));

      // Duplicates are kept: a boundary listed twice is reported twice, with the same values.
      std::vector<ReactionBoundary> boundaries;
      for (const auto &[name, id] : supported)
        boundaries.push_back(
          {name, id, moment_points.count(name) ? moment_points[name] : Point<3>()});
      return boundaries;
    }

    // Reaction force and moment on every supported boundary, from the residual at its DoFs.
    // Returns the moments by boundary, for the rotational stiffnesses.
    template <class Problem, int dim = Problem::dimension>
    std::map<std::string, Tensor<1, 3>> add_reactions(const Problem                     &problem,
                                                      const PETScWrappers::MPI::Vector &residual,
                                                      const DofLocations<dim>          &locations,
                                                      Quantities                       &q)
    {
      std::map<std::string, Tensor<1, 3>> moments;
      for (const auto &[name, id, x0] : reaction_boundaries(problem))
        {
          const IndexSet boundary_dofs = boundary_displacement_dofs(problem, id);
          Tensor<1, 3>   force, moment;
          for (const auto &[dof, location] : locations)
            if (boundary_dofs.is_element(dof))
              {
                Tensor<1, 3> f, r;
                f[location.component] = residual[dof];
                // moments about the deformed positions in a geometrically nonlinear analysis
                const Point<dim> &x = problem.geometrically_nonlinear ? location.current : location.reference;
                for (unsigned int d = 0; d < dim; ++d)
                  r[d] = x[d] - x0[d];
                force += f;
                moment += cross_product_3d(r, f);
              }
          force  = Utilities::MPI::sum(force, problem.communicator);
          moment = Utilities::MPI::sum(moment, problem.communicator);
          moments[name] = moment;
          for (unsigned int d = 0; d < dim; ++d)
            q["reaction_force_" + name + "_" + axis_name[d]] = force[d];
          if (dim == 2)
            q["reaction_moment_" + name + "_z"] = moment[2];
          else
            for (unsigned int d = 0; d < 3; ++d)
              q["reaction_moment_" + name + "_" + axis_name[d]] = moment[d];
        }
      return moments;
    }

    // Stiffness of each driven boundary: its reaction over the applied rotation or displacement.
    // Needs the reactions in q and their moments (every driven rotation is a supported boundary).
    template <class Problem, int dim = Problem::dimension>
    void add_stiffnesses(const Problem                             &problem,
                         const std::map<std::string, Tensor<1, 3>> &moments,
                         Quantities                                &q)
    {
      const auto &bc = problem.boundary_conditions;
      for (const auto &r : bc.rotations)
        q["rotational_stiffness_" + r.boundary] =
          (moments.at(r.boundary) * r.axis) / (problem.load_factor * r.angle);
      for (const auto &d : bc.displacements)
        for (unsigned int c = 0; c < dim; ++c)
          if (d.is_constant && d.mask[c] && d.values[c] != 0)
            q["stiffness_" + d.boundary + "_" + axis_name[c]] =
              q["reaction_force_" + d.boundary + "_" + axis_name[c]] / (problem.load_factor * d.values[c]);
    }

    // Mean displacement over a boundary (surface average).
    template <class Problem, int dim = Problem::dimension>
    void add_mean_displacements(const Problem &problem, Quantities &q)
    {
      for (const auto &name : names_in(problem.parameters.mean_displacements))
        {
          const int         id = problem.geometry.boundary_ids.at(name);
          FEFaceValues<dim> fe_face_values(*problem.mapping, *problem.fe, *problem.face_quadrature,
                                           update_values | update_JxW_values);
          std::vector<Tensor<1, dim>> u(problem.face_quadrature->size());
          Tensor<1, dim>              integral;
          double                      measure = 0;
          for (const auto &cell : problem.dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto f : cell->face_indices())
                if (cell->face(f)->at_boundary() && (int)cell->face(f)->boundary_id() == id)
                  {
                    fe_face_values.reinit(cell, f);
                    fe_face_values[FEValuesExtractors::Vector(0)].get_function_values(problem.solution, u);
                    for (unsigned int k = 0; k < u.size(); ++k)
                      {
                        integral += u[k] * fe_face_values.JxW(k);
                        measure += fe_face_values.JxW(k);
                      }
                  }
          integral = Utilities::MPI::sum(integral, problem.communicator);
          measure  = Utilities::MPI::sum(measure, problem.communicator);
          for (unsigned int d = 0; d < dim; ++d)
            q["mean_displacement_" + name + "_" + axis_name[d]] = integral[d] / measure;
        }
    }

    // Best-fit rigid motion u ~ t + w x x of a boundary in the least-squares sense over its area,
    // (t, w) = N^-1 int R^T u dA with N = int R^T R dA (R: rigid_motion_row), so that the value
    // does not depend on where the mesh puts its nodes. N^-1 on every rank.
    template <class Problem, int dim = Problem::dimension>
    FullMatrix<double> rigid_fit_inverse(const Problem &problem, const int id)
    {
      FullMatrix<double>   normal(6, 6);
      FEFaceValues<dim>    face_values(*problem.mapping, *problem.fe, *problem.face_quadrature,
                                       update_quadrature_points | update_JxW_values);
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() && (int)cell->face(f)->boundary_id() == id)
              {
                face_values.reinit(cell, f);
                for (unsigned int k = 0; k < face_values.n_quadrature_points; ++k)
                  for (unsigned int c = 0; c < dim; ++c)
                    {
                      const auto row = rigid_motion_row(face_values.quadrature_point(k), c);
                      for (unsigned int i = 0; i < 6; ++i)
                        for (unsigned int j = 0; j < 6; ++j)
                          normal(i, j) += row[i] * row[j] * face_values.JxW(k);
                    }
              }
      // One sum per entry, in this order on every rank.
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = 0; j < 6; ++j)
          normal(i, j) = Utilities::MPI::sum(normal(i, j), problem.communicator);
      if (dim == 2) // t_z, w_x, w_y do not exist in plane models
        for (unsigned int i : {2u, 3u, 4u})
          normal(i, i) = 1;
      normal.gauss_jordan();
      return normal;
    }

    template <class Problem, int dim = Problem::dimension>
    void add_boundary_rotations(const Problem &problem, Quantities &q)
    {
      FEFaceValues<dim> face_values(*problem.mapping, *problem.fe, *problem.face_quadrature,
                                    update_values | update_quadrature_points | update_JxW_values);
      std::vector<Tensor<1, dim>> u(face_values.n_quadrature_points);
      for (const auto &name : names_in(problem.parameters.rotations))
        {
          const int      id = problem.geometry.boundary_ids.at(name);
          Vector<double> rhs(6), tw(6);
          for (const auto &cell : problem.dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto f : cell->face_indices())
                if (cell->face(f)->at_boundary() && (int)cell->face(f)->boundary_id() == id)
                  {
                    face_values.reinit(cell, f);
                    face_values[FEValuesExtractors::Vector(0)].get_function_values(problem.solution, u);
                    for (unsigned int k = 0; k < u.size(); ++k)
                      for (unsigned int c = 0; c < dim; ++c)
                        {
                          const auto row = rigid_motion_row(face_values.quadrature_point(k), c);
                          for (unsigned int i = 0; i < 6; ++i)
                            rhs(i) += row[i] * u[k][c] * face_values.JxW(k);
                        }
                  }
          for (unsigned int i = 0; i < 6; ++i)
            rhs(i) = Utilities::MPI::sum(rhs(i), problem.communicator);
          rigid_fit_inverse(problem, id).vmult(tw, rhs);
          if (dim == 2)
            q["rotation_" + name + "_z"] = tw(5);
          else
            for (unsigned int d = 0; d < 3; ++d)
              q["rotation_" + name + "_" + axis_name[d]] = tw(3 + d);
        }
    }

    // Rigid boundaries: the exact rotation (radians) and the displacement of the moment centre.
    template <class Problem, int dim = Problem::dimension>
    void add_rigid_motions(const Problem &problem, Quantities &q)
    {
      for (const auto &rigid : problem.rigid_boundaries)
        {
          const auto  motion = rigid.motion(problem.solution, problem.geometrically_nonlinear);
          const auto &name   = rigid.load.boundary;
          if (dim == 2)
            q["rigid_rotation_" + name + "_z"] = motion.rotation[2];
          else
            for (unsigned int d = 0; d < 3; ++d)
              q["rigid_rotation_" + name + "_" + axis_name[d]] = motion.rotation[d];
          for (unsigned int d = 0; d < dim; ++d)
            q["rigid_displacement_" + name + "_" + axis_name[d]] = motion.displacement[d];
        }
    }

    // Peak von Mises over quadrature points and element nodes (with its location), strain
    // energy, and the yield safety factor.
    template <class Problem, int dim = Problem::dimension>
    void add_peak_stress_and_energy(const Problem &problem, Quantities &q)
    {
      MPI_Comm              comm   = problem.communicator;
      const Quadrature<dim> sample = peak_sample_points(*problem.quadrature, *problem.fe);
      const bool            has_pressure = problem.fe->n_components() > dim;
      const FEValuesExtractors::Vector u(0);
      const FEValuesExtractors::Scalar pressure(has_pressure ? dim : 0);
      FEValues<dim> sample_values(*problem.mapping, *problem.fe, sample,
                                  update_values | update_gradients | update_quadrature_points);
      FEValues<dim> fe_values(*problem.mapping, *problem.fe, *problem.quadrature,
                              update_values | update_gradients | update_JxW_values);
      std::vector<Tensor<2, dim>> grad(sample.size()), grad_q(problem.quadrature->size());
      std::vector<double>         p_values(sample.size(), 0.0), p_q(problem.quadrature->size(), 0.0);
      double     max_vm = -1, energy = 0, safety = std::numeric_limits<double>::max();
      Point<dim> max_location;
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const Material &material = problem.materials.at(cell->material_id());
            sample_values.reinit(cell);
            sample_values[u].get_function_gradients(problem.solution, grad);
            if (has_pressure)
              sample_values[pressure].get_function_values(problem.solution, p_values);
            for (unsigned int k = 0; k < sample.size(); ++k)
              {
                double       sigma_zz;
                const auto   sigma = problem.cauchy_stress(grad[k], material, p_values[k], sigma_zz);
                const double vm    = problem.von_mises(sigma, sigma_zz);
                if (vm > max_vm)
                  max_vm = vm, max_location = sample_values.quadrature_point(k);
                if (material.yield_strength > 0 && vm > 0)
                  safety = std::min(safety, material.yield_strength / vm);
              }
            fe_values.reinit(cell);
            fe_values[u].get_function_gradients(problem.solution, grad_q);
            if (has_pressure)
              fe_values[pressure].get_function_values(problem.solution, p_q);
            for (unsigned int k = 0; k < grad_q.size(); ++k)
              energy += problem.energy_density(grad_q[k], material, p_q[k]) * fe_values.JxW(k) *
                        problem.thickness;
          }
      const auto [global_max, location] = global_peak(max_vm, max_location, comm);
      q["max_von_mises"] = global_max;
      for (unsigned int d = 0; d < dim; ++d)
        q[std::string("max_von_mises_") + axis_name[d]] = location[d];
      q["strain_energy"]       = Utilities::MPI::sum(energy, comm);
      q["yield_safety_factor"] = Utilities::MPI::min(safety, comm);
    }

  } // namespace

  template <class Problem>
  void validate_quantity_requests(const Problem &problem)
  {
    const auto &p = problem.parameters;
    constexpr int dim = Problem::dimension;
    for (const auto &[name, point] : requested_points<dim>(p))
      {
        bool found = false;
        point_displacement(problem, point, found);
        if (!found)
          throw std::invalid_argument("Quantities/Points: point '" + name +
                                      "' lies outside the mesh");
      }
    for (const auto &[name, point] : reaction_points<dim>(p))
      boundary_id_of(name, problem.geometry.boundary_ids, "Quantities/Reactions");
    for (const auto &name : names_in(p.mean_displacements))
      boundary_id_of(name, problem.geometry.boundary_ids, "Quantities/Mean displacements");
    for (const auto &name : names_in(p.rotations))
      boundary_id_of(name, problem.geometry.boundary_ids, "Quantities/Rotations");
    validate_region_maxima(problem);
    validate_point_stresses(problem);
  }

  // Each step below runs its MPI collectives on every rank; keep their order.
  template <class Problem>
  Quantities compute_quantities(const Problem &problem)
  {
    Quantities q;
    add_mesh_sizes(problem, q);
    add_point_displacements(problem, q);

    const auto residual  = problem.reaction_forces();
    const auto locations = owned_dof_locations(problem);
    const auto moments   = add_reactions(problem, residual, locations, q);
    add_stiffnesses(problem, moments, q);
    add_mean_displacements(problem, q);
    add_boundary_rotations(problem, q);
    add_rigid_motions(problem, q);
    add_peak_stress_and_energy(problem, q);
    add_region_maxima(problem, q);
    add_point_stresses(problem, q);
    return q;
  }

  // The reaction quantities as sums of the residual at their boundary's DoFs,
  // name = scale (f . F + m . M) with F = sum r_i e_c(i), M = sum (x_i - x0) x r_i e_c(i):
  // psi_i = scale (f + m x (x_i - x0))_c(i).
  template <int dim>
  bool reaction_weights(const LinearElasticProblem<dim> &problem, const std::string &name,
                        PETScWrappers::MPI::Vector &psi)
  {
    const auto &bc = problem.boundary_conditions;
    for (const auto &[boundary, id, x0] : reaction_boundaries(problem))
      {
        Tensor<1, 3> f, m;
        double       scale = 1;
        for (unsigned int d = 0; d < 3; ++d)
          {
            if (d < dim && name == "reaction_force_" + boundary + "_" + axis_name[d])
              f[d] = 1;
            if ((dim == 3 || d == 2) && name == "reaction_moment_" + boundary + "_" + axis_name[d])
              m[d] = 1;
          }
        for (const auto &r : bc.rotations)
          if (r.boundary == boundary && name == "rotational_stiffness_" + boundary)
            m = r.axis, scale = 1 / (problem.load_factor * r.angle);
        for (const auto &d : bc.displacements)
          for (unsigned int c = 0; c < dim; ++c)
            if (d.boundary == boundary && name == "stiffness_" + boundary + "_" + axis_name[c] && d.is_constant &&
                d.mask[c] && d.values[c] != 0)
              f[c] = 1, scale = 1 / (problem.load_factor * d.values[c]);
        if (f.norm() == 0 && m.norm() == 0)
          continue;
        psi.reinit(problem.locally_owned_dofs, problem.communicator);
        const IndexSet boundary_dofs = boundary_displacement_dofs(problem, id);
        for (const auto &[dof, location] : owned_dof_locations(problem))
          if (boundary_dofs.is_element(dof))
            {
              Tensor<1, 3> r;
              for (unsigned int d = 0; d < dim; ++d)
                r[d] = location.reference[d] - x0[d];
              psi[dof] = scale * (f + cross_product_3d(m, r))[location.component];
            }
        psi.compress(VectorOperation::insert);
        return true;
      }
    return false;
  }

  template <int dim>
  bool rotation_weights(const LinearElasticProblem<dim> &problem, const std::string &name,
                        std::array<double, 6> &g, int &boundary_id)
  {
    for (const auto &boundary : names_in(problem.parameters.rotations))
      for (unsigned int d = (dim == 2 ? 2 : 0); d < 3; ++d)
        if (name == "rotation_" + boundary + "_" + axis_name[d])
          {
            boundary_id         = problem.geometry.boundary_ids.at(boundary);
            const auto inverse = rigid_fit_inverse(problem, boundary_id);
            for (unsigned int m = 0; m < 6; ++m)
              g[m] = inverse(3 + d, m);
            return true;
          }
    return false;
  }

  template void validate_quantity_requests(const LinearElasticProblem<2> &);
  template void validate_quantity_requests(const LinearElasticProblem<3> &);
  template Quantities compute_quantities(const LinearElasticProblem<2> &);
  template Quantities compute_quantities(const LinearElasticProblem<3> &);
  template void validate_quantity_requests(const FiniteStrainProblem<2> &);
  template void validate_quantity_requests(const FiniteStrainProblem<3> &);
  template Quantities compute_quantities(const FiniteStrainProblem<2> &);
  template Quantities compute_quantities(const FiniteStrainProblem<3> &);
  template bool reaction_weights(const LinearElasticProblem<2> &, const std::string &, PETScWrappers::MPI::Vector &);
  template bool reaction_weights(const LinearElasticProblem<3> &, const std::string &, PETScWrappers::MPI::Vector &);
  template bool rotation_weights(const LinearElasticProblem<2> &, const std::string &, std::array<double, 6> &, int &);
  template bool rotation_weights(const LinearElasticProblem<3> &, const std::string &, std::array<double, 6> &, int &);
} // namespace compliant
