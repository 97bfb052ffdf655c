// Rigid obstacles a part may touch (case-file section Contact): a plane (half-space), a circle
// (2D) or cylinder (3D), a sphere, each translated by `motion` times the load factor. An obstacle
// knows only its signed distance: gap(x) > 0 outside it, with the outward normal (from the
// obstacle towards the part), whose linearisation n . du drives the contact constraints, and its
// Coulomb friction coefficient.
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace compliant
{
  struct ContactSettings
  {
    std::string obstacles;  // 'name: plane, point=..., normal=...; ...'
    std::string boundaries; // the part's boundaries that may touch every obstacle
    std::string pairs;      // 'name: slave=..., master=...; ...': boundaries of the part touching each other
    double      tolerance = 1e-8; // largest penetration, as a fraction of the part's size
    bool        empty() const
    {
      return obstacles.find_first_not_of(" \t") == std::string::npos &&
             pairs.find_first_not_of(" \t") == std::string::npos;
    }
  };

  // Subsection Contact (nonlinear static analyses).
  void            declare_contact_parameters(dealii::ParameterHandler &prm);
  ContactSettings read_contact_settings(const dealii::ParameterHandler &prm);

  template <int dim>
  struct Obstacle
  {
    enum class Kind
    {
      plane,
      cylinder, // a circle in 2D
      sphere
    };
    std::string            name;
    Kind                   kind = Kind::plane;
    dealii::Point<dim>     point;     // plane: a point of it; cylinder, sphere: the centre
    dealii::Tensor<1, dim> direction; // plane: unit normal towards the part; cylinder: unit axis (3D)
    double                 radius = 0;
    dealii::Tensor<1, dim> motion; // translation at load factor 1
    double                 friction = 0; // Coulomb coefficient mu (0: frictionless)
    std::set<int>          boundary_ids;

    // Signed distance of x from the surface at the load factor, and the unit outward normal there.
    double gap(const dealii::Point<dim> &x, double load_factor, dealii::Tensor<1, dim> &normal) const;
  };

  // Parses Contact/Obstacles against the mesh's boundary names; throws std::invalid_argument
  // naming the entry, the obstacle and the parameter.
  template <int dim>
  std::vector<Obstacle<dim>> parse_obstacles(const ContactSettings                &settings,
                                             const std::map<std::string, int>    &boundaries,
                                             const std::map<std::string, double> &variables);
} // namespace compliant
