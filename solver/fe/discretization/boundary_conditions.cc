#include "discretization/boundary_conditions.h"

#include "input/expression.h"
#include "input/spec_list.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  int boundary_id_of(const std::string &name, const std::map<std::string, int> &boundaries,
                     const std::string &where)
  {
    const auto it = boundaries.find(name);
    if (it != boundaries.end())
      return it->second;
    std::string known;
    for (const auto &b : boundaries)
      known += " '" + b.first + "'";
    throw std::invalid_argument(where + ": unknown boundary '" + name +
                                "'; the mesh's boundary names are:" +
                                (known.empty() ? " (none)" : known));
  }

  template <int dim>
  dealii::Tensor<1, dim> parse_vector(const std::string &text, const std::string &where)
  {
    const auto v = parse_numbers(text, where);
    if (v.size() != dim && !(dim == 2 && v.size() == 3 && v[2] == 0))
      throw std::invalid_argument(where + ": expected " + std::to_string(dim) +
                                  " components, got '" + text + "'");
    dealii::Tensor<1, dim> t;
    for (unsigned int d = 0; d < dim; ++d)
      t[d] = v[d];
    return t;
  }

  namespace
  {
    int component_index(const std::string &key, int dim, const std::string &where)
    {
      if (key == "x")
        return 0;
      if (key == "y")
        return 1;
      if (key == "z" && dim == 3)
        return 2;
      throw std::invalid_argument(where + ": unknown component '" + key + "'; expected x, y" +
                                  (dim == 3 ? ", z" : ""));
    }

    // Reads one entry of the case after another into bc; claim refuses a boundary given two
    // conditions.
    template <int dim>
    class Resolver
    {
    public:
      Resolver(const CaseParameters &p, const std::map<std::string, int> &boundaries)
        : p(p)
        , boundaries(boundaries)
      {}

      void clamped()
      {
        const std::string where = "Boundary conditions/Clamped";
        for (const auto &name : split(p.clamped, ','))
          if (!name.empty())
            {
              claim(name, where);
              bc.clamped.emplace_back(name, boundary_id_of(name, boundaries, where));
            }
      }

      void displacements()
      {
        const std::string where = "Boundary conditions/Displacement";
        for (const auto &item : parse_spec_list(p.displacement, where))
          {
            claim(item.name, where);
            PrescribedDisplacement<dim> d;
            d.boundary    = item.name;
            d.boundary_id = boundary_id_of(item.name, boundaries, where);
            d.mask.assign(dim, false);
            d.values.assign(dim, 0.0);
            d.expressions.assign(dim, "0");
            if (item.fields.empty())
              throw std::invalid_argument(where + ": '" + item.name + "' names no component");
            for (const auto &f : item.fields)
              {
                const int c      = component_index(f.key, dim, where);
                d.mask[c]        = true;
                d.expressions[c] = f.value;
                // A number is a constant; anything else is a muparser expression of x, y, z.
                try
                  {
                    const auto v = parse_numbers(f.value, where);
                    if (v.size() != 1)
                      throw std::invalid_argument("");
                    d.values[c] = v[0];
                  }
                catch (const std::invalid_argument &)
                  {
                    d.is_constant = false;
                  }
              }
            bc.displacements.push_back(d);
          }
      }

      void rotations()
      {
        const std::string where = "Boundary conditions/Rotation";
        for (const auto &item : parse_spec_list(p.rotation, where))
          {
            claim(item.name, where);
            PrescribedRotation<dim> r;
            r.boundary    = item.name;
            r.boundary_id = boundary_id_of(item.name, boundaries, where);
            if (item.has("angle") == item.has("degrees"))
              throw std::invalid_argument(where + ": '" + item.name +
                                          "' needs exactly one of angle=<radians> or degrees=<deg>");
            for (const auto &f : item.fields)
              if (f.key != "angle" && f.key != "degrees" && f.key != "center" && f.key != "axis")
                throw std::invalid_argument(where + ": unknown field '" + f.key + "' of '" +
                                            item.name + "'; expected angle|degrees, center, axis");
            r.angle = item.has("angle") ? parse_numbers(item.get("angle"), where).at(0) :
                                          parse_numbers(item.get("degrees"), where).at(0) * M_PI / 180;
            const auto c = evaluate_coordinates(item.get("center"), p.geometry_parameters,
                                                where + " center of '" + item.name + "'");
            if (!(c.size() == (unsigned)dim || (c.size() == 3 && dim == 2)))
              throw std::invalid_argument(where + ": center of '" + item.name + "' needs " +
                                          std::to_string(dim) + " coordinates");
            for (unsigned int d = 0; d < c.size(); ++d)
              r.center[d] = c[d];
            r.axis = dealii::Tensor<1, 3>({0., 0., 1.});
            if (item.has("axis"))
              {
                const auto a = parse_numbers(item.get("axis"), where + " axis");
                if (a.size() != 3)
                  throw std::invalid_argument(where + ": axis of '" + item.name +
                                              "' needs 3 components");
                r.axis = dealii::Tensor<1, 3>({a[0], a[1], a[2]});
                if (r.axis.norm() == 0)
                  throw std::invalid_argument(where + ": axis of '" + item.name + "' is zero");
                r.axis /= r.axis.norm();
                if (dim == 2 && std::abs(r.axis[2]) != 1)
                  throw std::invalid_argument(where + ": in 2D the axis must be z (0 0 1)");
              }
            bc.rotations.push_back(r);
          }
      }

      void rigid()
      {
        const std::string where = "Boundary conditions/Rigid";
        for (const auto &item : parse_spec_list(p.rigid, where))
          {
            claim(item.name, where);
            RigidBoundaryLoad<dim> r;
            r.boundary    = item.name;
            r.boundary_id = boundary_id_of(item.name, boundaries, where);
            for (const auto &f : item.fields)
              if (f.key != "moment" && f.key != "force" && f.key != "center")
                throw std::invalid_argument(where + ": unknown field '" + f.key + "' of '" +
                                            item.name + "'; expected moment, force, center");
            if (item.has("force"))
              {
                const auto f = evaluate_coordinates(item.get("force"), p.geometry_parameters,
                                                    where + " force of '" + item.name + "'");
                if (!(f.size() == (unsigned)dim || (dim == 2 && f.size() == 3 && f[2] == 0)))
                  throw std::invalid_argument(where + ": force of '" + item.name + "' needs " +
                                              std::to_string(dim) + " components");
                for (unsigned int d = 0; d < dim; ++d)
                  r.force[d] = f[d];
              }
            if (item.has("moment"))
              {
                const auto m = evaluate_coordinates(item.get("moment"), p.geometry_parameters,
                                                    where + " moment of '" + item.name + "'");
                if (dim == 2 && m.size() == 1)
                  r.moment[2] = m[0];
                else if (dim == 3 && m.size() == 3)
                  r.moment = dealii::Tensor<1, 3>({m[0], m[1], m[2]});
                else
                  throw std::invalid_argument(where + ": moment of '" + item.name + "' needs " +
                                              (dim == 2 ? "one number (about z)" : "3 components"));
              }
            for (unsigned int d = 0; d < 3; ++d)
              if (!std::isfinite(r.moment[d]) || (d < dim && !std::isfinite(r.force[d])))
                throw std::invalid_argument(where + ": force and moment of '" + item.name +
                                            "' must be finite numbers");
            if (item.has("center"))
              {
                const auto c = evaluate_coordinates(item.get("center"), p.geometry_parameters,
                                                    where + " center of '" + item.name + "'");
                if (!(c.size() == (unsigned)dim || (c.size() == 3 && dim == 2)))
                  throw std::invalid_argument(where + ": center of '" + item.name + "' needs " +
                                              std::to_string(dim) + " coordinates");
                r.has_center = true;
                for (unsigned int d = 0; d < c.size(); ++d)
                  r.center[d] = c[d];
              }
            bc.rigid.push_back(r);
          }
      }

      void tractions()
      {
        const std::string where = "Loads/Traction";
        for (const auto &item : parse_spec_list(p.traction, where))
          {
            if (item.fields.size() != 1 || !item.fields[0].key.empty())
              throw std::invalid_argument(where + ": expected 'boundary: fx fy [fz]'");
            const int id = boundary_id_of(item.name, boundaries, where);
            try
              {
                bc.tractions[id] += parse_vector<dim>(item.fields[0].value, where);
              }
            catch (const std::invalid_argument &)
              {
                // Not numbers: one expression of x, y, z per component, e.g. "0 (1-y^2)".
                std::istringstream       in(item.fields[0].value);
                std::vector<std::string> components;
                for (std::string c; in >> c;)
                  components.push_back(c);
                if (components.size() != dim || bc.traction_fields.count(id))
                  throw std::invalid_argument(where + ": '" + item.name + "' needs " +
                                              std::to_string(dim) +
                                              " space-separated numbers or expressions");
                bc.traction_fields[id] = components;
              }
          }
      }

      void pressures()
      {
        const std::string where = "Loads/Pressure";
        for (const auto &item : parse_spec_list(p.pressure, where))
          {
            if (item.fields.size() != 1 || !item.fields[0].key.empty() || trim(item.fields[0].value).empty())
              throw std::invalid_argument(where + ": expected 'boundary: p' (a number or an expression "
                                          "of x, y, z)");
            const int id = boundary_id_of(item.name, boundaries, where);
            if (bc.pressures.count(id))
              throw std::invalid_argument(where + ": '" + item.name + "' is given twice");
            bc.pressures[id] = trim(item.fields[0].value);
          }
      }

      void total_forces()
      {
        const std::string where = "Loads/Total force";
        for (const auto &item : parse_spec_list(p.total_force, where))
          {
            if (item.fields.size() != 1 || !item.fields[0].key.empty())
              throw std::invalid_argument(where + ": expected 'boundary: Fx Fy [Fz]'");
            boundary_id_of(item.name, boundaries, where);
            bc.total_forces[item.name] += parse_vector<dim>(item.fields[0].value, where);
          }
      }

      BoundaryConditions<dim> bc;

    private:
      void claim(const std::string &name, const std::string &entry)
      {
        if (used.count(name))
          throw std::invalid_argument("Boundary conditions: boundary '" + name + "' appears in both " +
                                      used[name] + " and " + entry);
        used[name] = entry;
      }

      const CaseParameters               &p;
      const std::map<std::string, int>   &boundaries;
      std::map<std::string, std::string> used; // boundary -> entry
    };
  } // namespace

  template <int dim>
  BoundaryConditions<dim> resolve_boundary_conditions(const CaseParameters             &p,
                                                      const std::map<std::string, int> &boundaries)
  {
    Resolver<dim> resolver(p, boundaries);
    resolver.clamped();
    resolver.displacements();
    resolver.rotations();
    resolver.rigid();
    resolver.tractions();
    resolver.pressures();
    resolver.total_forces();
    BoundaryConditions<dim> &bc = resolver.bc;
    if (!trim(p.body_force).empty())
      bc.body_force = parse_vector<dim>(p.body_force, "Loads/Body force");
    if (!trim(p.gravity).empty())
      bc.gravity = parse_vector<dim>(p.gravity, "Loads/Gravity");
    return bc;
  }

  template BoundaryConditions<2> resolve_boundary_conditions<2>(const CaseParameters &,
                                                                const std::map<std::string, int> &);
  template BoundaryConditions<3> resolve_boundary_conditions<3>(const CaseParameters &,
                                                                const std::map<std::string, int> &);
  template dealii::Tensor<1, 2> parse_vector<2>(const std::string &, const std::string &);
  template dealii::Tensor<1, 3> parse_vector<3>(const std::string &, const std::string &);
} // namespace compliant
