#include "contact/contact_obstacle.h"

#include "discretization/boundary_conditions.h"
#include "input/expression.h"
#include "input/spec_list.h"

#include <cmath>
#include <stdexcept>

namespace compliant
{
  using namespace dealii;

  void declare_contact_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry(
      "Obstacles", "", Patterns::Anything(),
      "Rigid obstacles the part may touch (nonlinear static analyses): "
      "'stop: plane, point=x y [z], normal=nx ny [nz]; pin: circle, center=x y, radius=r; "
      "former: cylinder, center=x y z, axis=ax ay az, radius=r; ball: sphere, center=x y z, "
      "radius=r'. A plane's normal points from the obstacle towards the part (the obstacle is "
      "the half-space behind it); circle is 2D, cylinder (axis) and sphere 3D (cylinder in 2D is a "
      "circle). Optional per obstacle: motion=dx dy [dz], a rigid translation reached at load "
      "factor 1 (scaled by the load factor), friction=mu, a Coulomb coefficient (default 0, "
      "frictionless: a held node sticks while its tangential force stays within mu times its "
      "normal force, and slips against mu times it beyond), and boundaries=name name, the part's "
      "boundaries that may touch it (default: Contact/Boundaries). Values may be expressions of geometry "
      "parameters. Solved by a primal-dual active set (semismooth Newton, as deal.II step-41): "
      "each node of those boundaries is either free or held on the obstacle surface, decided "
      "inside Newton from its gap and contact force; no penalty stiffness. Gives "
      "contact_force_<name>_<x|y|z> (on the part), contact_moment_<name>_<z|x y z> (about the "
      "origin, deformed positions), contact_nodes_<name> (with friction also "
      "contact_sticking_nodes_<name> and contact_slipping_nodes_<name>), contact_active_nodes (per step in "
      "curve.csv), contact_max_penetration and contact_penetration_tolerance; contact.csv lists "
      "every contact node (position, gap, force, pressure).");
    prm.declare_entry("Boundaries", "", Patterns::Anything(),
                      "The part's boundaries that may touch every obstacle: 'bottom, side' (commas, "
                      "spaces or semicolons between names).");
    prm.declare_entry(
      "Pairs", "", Patterns::Anything(),
      "Boundaries of the part that may touch each other (nonlinear static analyses, quadrilateral "
      "and hexahedral meshes, frictionless): 'stop: slave=tip, master=stop_face; fold: slave=a b, "
      "master=c'. The slave boundary's nodes are held outside the master surface by the same "
      "active set as the obstacles, in mortar form (each node's gap and constraint weighted over "
      "its faces, the master's nodes sharing its force), so a uniform pressure passes exactly "
      "across a flat contact also between meshes that do not match. The two bodies of a pair may "
      "be separate parts of one mesh, or one part touching itself. Gives contact_force_<name>_<x|y|z> "
      "(on the slave side; the master carries the opposite), contact_moment_<name>_<z|x y z> and "
      "contact_nodes_<name>, and rows of contact.csv.");
    prm.declare_entry("Penetration tolerance", "1e-8", Patterns::Double(0, 1e-2),
                      "A load step converges only when no contact node lies deeper than this "
                      "fraction of the part's size (its bounding-box diagonal) inside an "
                      "obstacle and every held node lies on it within it (checked at the nodes).");
    prm.leave_subsection();
  }

  ContactSettings read_contact_settings(const ParameterHandler &prm)
  {
    ContactSettings s;
    s.obstacles  = prm.get({"Contact"}, "Obstacles");
    s.boundaries = prm.get({"Contact"}, "Boundaries");
    s.pairs      = prm.get({"Contact"}, "Pairs");
    s.tolerance  = std::stod(prm.get({"Contact"}, "Penetration tolerance"));
    return s;
  }

  template <int dim>
  double Obstacle<dim>::gap(const Point<dim> &x, const double load_factor, Tensor<1, dim> &normal) const
  {
    const Point<dim> reference = point + load_factor * motion;
    Tensor<1, dim>   r         = x - reference;
    if (kind == Kind::plane)
      {
        normal = direction;
        return r * direction;
      }
    if (kind == Kind::cylinder && dim == 3)
      r -= (r * direction) * direction;
    const double distance = r.norm();
    // On the axis or at the centre every direction is as good: take the first axis.
    normal = distance > 0 ? Tensor<1, dim>(r / distance) : Tensor<1, dim>();
    if (distance == 0)
      normal[0] = 1;
    return distance - radius;
  }

  namespace
  {
    template <int dim>
    Tensor<1, dim> vector_field(const SpecItem &item, const std::string &key, const std::map<std::string, double> &variables,
                                const std::string &where, const bool required)
    {
      Tensor<1, dim> v;
      if (!item.has(key))
        {
          if (required)
            throw std::invalid_argument(where + ": obstacle '" + item.name + "' needs " + key + "=" +
                                        (dim == 2 ? "x y" : "x y z"));
          return v;
        }
      const auto c = evaluate_coordinates(item.get(key), variables, where + " " + key + " of '" + item.name + "'");
      if (c.size() != dim && !(dim == 2 && c.size() == 3 && c[2] == 0))
        throw std::invalid_argument(where + ": " + key + " of obstacle '" + item.name + "' needs " +
                                    std::to_string(dim) + " numbers, got '" + item.get(key) + "'");
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = c[d];
      return v;
    }

    std::set<int> boundary_set(const std::string &names, const std::map<std::string, int> &boundaries,
                               const std::string &where)
    {
      std::set<int> ids;
      std::string   spaced = names;
      // Commas, spaces or (in Contact/Boundaries, like Quantities/Reactions) semicolons.
      for (char &c : spaced)
        if (c == ',' || c == ';')
          c = ' ';
      for (const auto &name : split(spaced, ' '))
        if (!name.empty())
          ids.insert(boundary_id_of(name, boundaries, where));
      return ids;
    }

    // The fields an obstacle of each kind takes, and those it must have.
    const std::map<std::string, std::pair<std::set<std::string>, std::set<std::string>>> &kind_fields()
    {
      static const std::map<std::string, std::pair<std::set<std::string>, std::set<std::string>>> fields{
        {"plane", {{"point", "normal", "motion", "friction", "boundaries"}, {"point", "normal"}}},
        {"circle", {{"center", "radius", "motion", "friction", "boundaries"}, {"center", "radius"}}},
        {"cylinder", {{"center", "radius", "axis", "motion", "friction", "boundaries"}, {"center", "radius"}}},
        {"sphere", {{"center", "radius", "motion", "friction", "boundaries"}, {"center", "radius"}}}};
      return fields;
    }
  } // namespace

  template <int dim>
  std::vector<Obstacle<dim>> parse_obstacles(const ContactSettings &settings, const std::map<std::string, int> &boundaries,
                                             const std::map<std::string, double> &variables)
  {
    const std::string where = "Contact/Obstacles";
    const auto common = boundary_set(settings.boundaries, boundaries, "Contact/Boundaries");
    std::vector<Obstacle<dim>> obstacles;
    for (const auto &item : parse_spec_list(settings.obstacles, where))
      {
        Obstacle<dim> o;
        o.name = item.name;
        for (const auto &other : obstacles)
          if (other.name == o.name)
            throw std::invalid_argument(where + ": obstacle '" + o.name + "' given twice");
        std::string kind;
        for (const auto &f : item.fields)
          if (f.key.empty())
            {
              if (!kind.empty())
                throw std::invalid_argument(where + ": obstacle '" + o.name + "' has two kinds ('" + kind + "', '" +
                                            f.value + "')");
              kind = f.value;
            }
        const auto known = kind_fields().find(kind);
        if (known == kind_fields().end())
          throw std::invalid_argument(where + ": obstacle '" + o.name + "' needs its kind first: plane, " +
                                      (dim == 2 ? "circle" : "cylinder, sphere") + " (got '" + kind + "')");
        if ((kind == "sphere" && dim == 2) || (kind == "circle" && dim == 3))
          throw std::invalid_argument(where + ": obstacle '" + o.name + "': a " + kind + " is " +
                                      (dim == 2 ? "3D; in 2D use circle" : "2D; in 3D use cylinder or sphere"));
        for (const auto &f : item.fields)
          if (!f.key.empty() && known->second.first.count(f.key) == 0)
            throw std::invalid_argument(where + ": obstacle '" + o.name + "' (" + kind + ") has no parameter '" +
                                        f.key + "'");
        for (const auto &key : known->second.second)
          if (!item.has(key))
            throw std::invalid_argument(where + ": obstacle '" + o.name + "' (" + kind + ") needs " + key + "=");
        o.motion = vector_field<dim>(item, "motion", variables, where, false);
        if (item.has("friction"))
          {
            o.friction = evaluate_expression(item.get("friction"), variables, where + " friction of '" + o.name + "'");
            if (!(o.friction >= 0) || !std::isfinite(o.friction))
              throw std::invalid_argument(where + ": friction of obstacle '" + o.name +
                                          "' must be a coefficient >= 0 (0: frictionless), got '" +
                                          item.get("friction") + "'");
          }
        if (kind == "plane")
          {
            o.point     = Point<dim>(vector_field<dim>(item, "point", variables, where, true));
            o.direction = vector_field<dim>(item, "normal", variables, where, true);
          }
        else
          {
            o.kind   = kind == "sphere" ? Obstacle<dim>::Kind::sphere : Obstacle<dim>::Kind::cylinder;
            o.point  = Point<dim>(vector_field<dim>(item, "center", variables, where, true));
            o.radius = evaluate_expression(item.get("radius"), variables, where + " radius of '" + o.name + "'");
            if (!(o.radius > 0) || !std::isfinite(o.radius))
              throw std::invalid_argument(where + ": radius of obstacle '" + o.name + "' must be positive");
            if (kind == "cylinder" && dim == 3)
              o.direction = vector_field<dim>(item, "axis", variables, where, true);
          }
        if ((kind == "plane" || (kind == "cylinder" && dim == 3)))
          {
            const double length = o.direction.norm();
            if (!(length > 0) || !std::isfinite(length))
              throw std::invalid_argument(where + ": the " + (kind == "plane" ? "normal" : "axis") + " of obstacle '" +
                                          o.name + "' must be a non-zero vector");
            o.direction /= length;
          }
        o.boundary_ids = item.has("boundaries") ?
                           boundary_set(item.get("boundaries"), boundaries, where + " boundaries of '" + o.name + "'") :
                           common;
        if (o.boundary_ids.empty())
          throw std::invalid_argument(where + ": obstacle '" + o.name + "' touches no boundary: name them in "
                                      "Contact/Boundaries or boundaries=... of the obstacle");
        obstacles.push_back(o);
      }
    if (obstacles.empty() && !common.empty())
      throw std::invalid_argument("Contact/Boundaries: boundaries are named but Contact/Obstacles is empty");
    return obstacles;
  }

  template struct Obstacle<2>;
  template struct Obstacle<3>;
  template std::vector<Obstacle<2>> parse_obstacles(const ContactSettings &, const std::map<std::string, int> &,
                                                    const std::map<std::string, double> &);
  template std::vector<Obstacle<3>> parse_obstacles(const ContactSettings &, const std::map<std::string, int> &,
                                                    const std::map<std::string, double> &);
} // namespace compliant
