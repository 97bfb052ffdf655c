#include "discretization/discretization.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/lac/la_parallel_vector.h>

#include "discretization/reduced_integration.h"
#include "mesh/curved_simplex_mapping.h"
#include "mesh/mesh_reader.h"

namespace compliant
{
  using namespace dealii;

  template <int dim>
  Discretization<dim>::Discretization(const CaseParameters &parameters, const MeshedGeometry &geometry,
                                      MPI_Comm communicator, const MeshPartitionChoice &partition)
    : parameters(parameters)
    , geometry(geometry)
    , communicator(communicator)
    , mesh_partition(partition)
    , triangulation_storage(make_triangulation<dim>(partition.partition, communicator))
    , triangulation(*triangulation_storage)
    , dof_handler(triangulation)
    , thickness(dim == 2 ? parameters.thickness : 1.0)
    , plane_stress(dim == 2 && parameters.model == Model::plane_stress)
  {}

  template <int dim>
  struct Discretization<dim>::ImperfectionField
  {
    explicit ImperfectionField(const Triangulation<dim> &triangulation)
      : dofs(triangulation)
    {}
    DoFHandler<dim>                            dofs;
    LinearAlgebra::distributed::Vector<double> shift;
  };

  template <int dim>
  Discretization<dim>::~Discretization()
  {
    mapping.reset(); // before the shift it refers to
  }

  namespace
  {
    // The imperfection's per-cell values on this mesh's own DoFs (ghosted, as the mapping reads
    // them on every cell it is used on).
    template <int dim>
    void fill_shift(const GeometryImperfection &imperfection, const DoFHandler<dim> &dofs,
                    LinearAlgebra::distributed::Vector<double> &shift, MPI_Comm communicator)
    {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dofs, relevant);
      shift.reinit(dofs.locally_owned_dofs(), relevant, communicator);
      std::vector<types::global_dof_index> indices(dofs.get_fe().n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto found = imperfection.cell_shift.find(cell->id());
            if (found == imperfection.cell_shift.end() || found->second.size() != indices.size())
              throw std::logic_error("Geometry/Imperfection: the mesh differs from the one the buckling "
                                     "modes were computed on");
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              if (shift.locally_owned_elements().is_element(indices[i]))
                shift(indices[i]) = found->second[i];
          }
      shift.update_ghost_values();
    }

    // The perfect mapping's support points (curved boundaries included) plus the shift there,
    // cached. (deal.II 9.4's MappingQEulerian starts from the straight-sided cell.)
    template <int dim>
    struct PerfectMapping : MappingQ<dim>
    {
      using MappingQ<dim>::MappingQ;
      using MappingQ<dim>::compute_mapping_support_points;
    };

    template <int dim>
    std::unique_ptr<Mapping<dim>> shifted_mapping_of(const DoFHandler<dim> &dofs,
                                                     const LinearAlgebra::distributed::Vector<double> &shift,
                                                     const unsigned int degree)
    {
      const PerfectMapping<dim> perfect(degree);
      // The mapping's support points in its (hierarchical) order: those of FE_Q on Gauss-Lobatto points.
      const Quadrature<dim> support(FE_Q<dim>(QGaussLobatto<1>(degree + 1)).get_unit_support_points());
      auto cache = std::make_unique<MappingQCache<dim>>(degree);
      cache->initialize(dofs.get_triangulation(), [&](const typename Triangulation<dim>::cell_iterator &cell) {
        auto points = perfect.compute_mapping_support_points(cell);
        if (!cell->is_active() || !(cell->is_locally_owned() || cell->is_ghost()))
          return points; // never assembled on this rank
        const typename DoFHandler<dim>::active_cell_iterator dof_cell(&dofs.get_triangulation(), cell->level(),
                                                                      cell->index(), &dofs);
        FEValues<dim> values(perfect, dofs.get_fe(), support, update_values);
        values.reinit(dof_cell);
        std::vector<Tensor<1, dim>> shifts(support.size());
        values[FEValuesExtractors::Vector(0)].get_function_values(shift, shifts);
        for (unsigned int i = 0; i < points.size(); ++i)
          points[i] += shifts[i];
        return points;
      });
      return cache;
    }
  } // namespace

  template <int dim>
  void Discretization<dim>::check_mesh_dimension() const
  {
    if (geometry.dimension != dim)
      throw std::invalid_argument("Model = " + std::string(to_string(parameters.model)) + " needs a " + std::to_string(dim) +
                                  "D mesh, but '" + parameters.mesh_file + "' is " +
                                  std::to_string(geometry.dimension) + "D");
  }

  template <int dim>
  void Discretization<dim>::create_mesh()
  {
    create_triangulation(triangulation, geometry, parameters.global_refinements, parameters.adaptive_refinements,
                         parameters.element_degree);
  }

  template <int dim>
  void Discretization<dim>::choose_element(const bool with_pressure)
  {
    const unsigned int degree = parameters.element_degree;
    // Discretization/Curved mapping degree; 0: isoparametric.
    const unsigned int curved_degree =
      parameters.curved_mapping_degree > 0 ? parameters.curved_mapping_degree : degree;
    if (triangulation.all_reference_cells_are_hyper_cube())
      {
        if (with_pressure)
          fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim, FE_DGP<dim>(degree - 1), 1);
        else
          fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim);
        if (imperfection)
          {
            mapping.reset();
            imperfection_field = std::make_unique<ImperfectionField>(triangulation);
            imperfection_field->dofs.distribute_dofs(FESystem<dim>(FE_Q<dim>(imperfection->degree), dim));
            fill_shift(*imperfection, imperfection_field->dofs, imperfection_field->shift, communicator);
            perfect_mapping = std::make_unique<MappingQ<dim>>(mapping_degree(geometry.curved, curved_degree));
            mapping = shifted_mapping_of(imperfection_field->dofs, imperfection_field->shift,
                                         std::max(mapping_degree(geometry.curved, curved_degree), imperfection->degree));
          }
        else
          mapping = std::make_unique<MappingQ<dim>>(mapping_degree(geometry.curved, curved_degree));
        quadrature = parameters.reduced_integration && !with_pressure ?
                       std::make_unique<Quadrature<dim>>(
                         stabilized_reduced_quadrature<dim>(degree, parameters.hourglass_stiffness)) :
                       std::make_unique<QGauss<dim>>(degree + 1);
        face_quadrature = std::make_unique<QGauss<dim - 1>>(degree + 1);
      }
    else if (parameters.reduced_integration)
      throw std::invalid_argument("Discretization/Integration = reduced needs quadrilaterals or hexahedra");
    else if (imperfection)
      throw std::invalid_argument("Geometry/Imperfection needs quadrilaterals or hexahedra");
    else if (triangulation.all_reference_cells_are_simplex() && !with_pressure)
      {
        if (degree > 2) // FE_SimplexP<2>(3) crashes in deal.II 9.4.1
          throw std::invalid_argument("Discretization/Element degree: triangles and tetrahedra "
                                      "support degree 1 or 2, not " + std::to_string(degree));
        fe              = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(degree), dim);
        mapping         = std::make_unique<CurvedSimplexMapping<dim>>(mapping_degree(geometry.curved, degree));
        quadrature      = std::make_unique<QGaussSimplex<dim>>(degree + 1);
        face_quadrature = std::make_unique<QGaussSimplex<dim - 1>>(degree + 1);
      }
    else if (with_pressure)
      throw std::invalid_argument("the mixed formulation needs quadrilaterals or hexahedra");
    else
      throw std::invalid_argument("mesh '" + parameters.mesh_file + "' mixes cell types");
  }

  template <int dim>
  void Discretization<dim>::assign_materials()
  {
    materials = compliant::assign_materials(parameters.materials, geometry.material_ids, parameters.unit_system);
  }

  template <int dim>
  void Discretization<dim>::resolve_boundary_conditions()
  {
    boundary_conditions = compliant::resolve_boundary_conditions<dim>(parameters, geometry.boundary_ids);
  }

  template <int dim>
  void Discretization<dim>::distribute_dofs()
  {
    dof_handler.distribute_dofs(*fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_node_constraints);
    hanging_node_constraints.close();
  }

  template <int dim>
  std::map<std::string, double> Discretization<dim>::expression_variables() const
  {
    return compliant::expression_variables(parameters.geometry_parameters, materials.begin()->second, thickness);
  }

  template class Discretization<2>;
  template class Discretization<3>;
} // namespace compliant
