#include "mesh/gmsh_geometry.h"

#include "mesh/abaqus_mesh.h"
#include "mesh/contained_call.h"
#include "mesh/interior_boundaries.h"
#include "mesh/memory_estimate.h"
#include "mesh/mesh_size_guard.h"

#include <deal.II/base/utilities.h>

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace compliant
{
  namespace
  {
    const std::string parameter_prefix = "Parameters/";

    // gmsh keeps global state: one session per call keeps calls independent.
    struct GmshSession
    {
      GmshSession()
      {
        gmsh::initialize();
        // The ONELAB parameters outlive finalize(): without this, a second geometry read in the
        // same process (a paired model) would seem to declare the first one's parameters.
        gmsh::onelab::clear();
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.Verbosity", 1);
        // gmsh's API throws at the first error, inside its OpenMP meshing region, where an
        // exception terminates the process: let errors be logged instead, and ask afterwards.
        gmsh::option::setNumber("General.AbortOnError", 0);
      }
      ~GmshSession()
      {
        try // may run while an exception unwinds: gmsh must not throw a second one
          {
            gmsh::finalize();
          }
        catch (...)
          {
          }
      }
    };

    bool file_exists(const std::string &file)
    {
      std::ifstream in(file);
      return in.good();
    }

    bool has_extension(const std::string &file, const std::string &extension)
    {
      return file.size() > extension.size() &&
             file.compare(file.size() - extension.size(), extension.size(), extension) == 0;
    }
    bool is_geo(const std::string &file) { return has_extension(file, ".geo"); }

    void open_or_throw(const std::string &file)
    {
      // gmsh guesses the format of other names, and a control character in the name sent it into
      // endless recursive merging (found by fuzzing): plain .geo and .msh names only.
      for (const char c : file)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
          throw std::runtime_error("the mesh file name contains a control character; expected a .geo or .msh file");
      if (!is_geo(file) && !has_extension(file, ".msh"))
        throw std::runtime_error("'" + file + "' is neither a .geo, .msh nor .inp file");
      if (!file_exists(file))
        throw std::runtime_error("geometry file '" + file + "' does not exist");
      try
        {
          gmsh::open(file);
        }
      catch (const std::exception &e)
        {
          throw std::runtime_error("gmsh could not read '" + file + "': " + e.what());
        }
      catch (...)
        {
          throw std::runtime_error("gmsh could not read '" + file + "'");
        }
    }

    // gmsh logs errors (General.AbortOnError = 0): the first one logged ends the run, by name.
    void throw_if_gmsh_error(const std::string &file, const std::string &stage)
    {
      std::string error;
      gmsh::logger::getLastError(error);
      if (!error.empty())
        throw std::runtime_error("gmsh could not " + stage + " '" + file + "': " + error +
                                 " (check the geometry parameters)");
    }

    // The ONELAB JSON has "help":"..."; a full JSON parser is not worth it for one field.
    std::string help_of(const std::string &name)
    {
      std::string json;
      gmsh::onelab::get(json, name);
      const std::string key = "\"help\":\"";
      const auto        pos = json.find(key);
      if (pos == std::string::npos)
        return "";
      const auto end = json.find('"', pos + key.size());
      return json.substr(pos + key.size(), end - pos - key.size());
    }
  } // namespace

  namespace
  {
    // gmsh's C++ API reports errors by throwing std::string (or const char *): turn them into
    // exceptions that name the file, so that a geometry gmsh cannot build is a clear input error.
    template <typename Function>
    auto with_gmsh_errors(const std::string &file, Function &&function)
    {
      try
        {
          return function();
        }
      catch (const std::string &message)
        {
          throw std::runtime_error("gmsh could not build the geometry of '" + file + "': " + message +
                                   " (check the geometry parameters)");
        }
      catch (const char *message)
        {
          throw std::runtime_error("gmsh could not build the geometry of '" + file + "': " +
                                   std::string(message) + " (check the geometry parameters)");
        }
    }

    constexpr std::uint64_t gigabyte = 1000000000;
    // Reading a .geo and meshing its curves needs little memory and time; what a full mesh may
    // take is known once its size is estimated.
    constexpr std::uint64_t memory_before_estimate  = gigabyte;
    constexpr double        seconds_before_estimate = 60;
    constexpr double        seconds_per_cell        = 1e-4; // measured 6 us per quadrilateral
    constexpr double        child_bytes_per_cell    = 4000; // gmsh's mesh + the text, copied twice

    template <typename T>
    std::string pack_to_string(const T &object)
    {
      const std::vector<char> bytes = dealii::Utilities::pack(object, false);
      return std::string(bytes.begin(), bytes.end());
    }

    template <typename T>
    T unpack_from_string(const std::string &text)
    {
      return dealii::Utilities::unpack<T>(std::vector<char>(text.begin(), text.end()), false);
    }

    // "'meshes/x.geo' with l=10, t=1e-06" for messages.
    std::string describe(const std::string &file, const std::map<std::string, double> &parameters)
    {
      std::ostringstream text;
      text << "'" << file << "'";
      const char *separator = " with ";
      for (const auto &[name, value] : parameters)
        {
          text << separator << name << "=" << value;
          separator = ", ";
        }
      return text.str();
    }

    // A crash, a time-out or memory running out in the child, said with the file and parameters.
    std::runtime_error child_failure(const ContainedCallFailed &failure, const std::string &file,
                                     const std::map<std::string, double> &parameters)
    {
      if (failure.kind == ContainedCallFailed::error)
        return std::runtime_error(failure.what());
      const std::string what = failure.what();
      const std::string of   = what.find(" while ") != std::string::npos ? " of " : " processing ";
      const char *advice =
        failure.kind == ContainedCallFailed::timed_out ?
          "; check the geometry parameters (Geometry/Meshing time limit sets the limit)" :
        failure.kind == ContainedCallFailed::out_of_memory ?
          "; check the geometry parameters (a length in the wrong unit asks for far more cells)" :
          "; check the geometry parameters";
      return std::runtime_error("gmsh " + what + of + describe(file, parameters) + advice);
    }

    struct SizeLimit
    {
      std::uint64_t maximum_cells = 0; // 0: none
      std::string   origin;            // how the maximum was set, for the message
      bool          automatic_time = true;
    };

    SizeLimit resolve_size_limit(const MeshingLimits &limits)
    {
      SizeLimit limit;
      limit.automatic_time = limits.seconds <= 0;
      if (limits.maximum_cells > 0)
        {
          limit.maximum_cells = limits.maximum_cells;
          limit.origin        = "Geometry/Maximum cells";
          return limit;
        }
      limit.maximum_cells = automatic_maximum_cells(limits.ranks);
      std::ostringstream origin;
      origin.precision(3);
      origin << "automatic: " << available_memory() / 1e9 << " GB available at ~1 kB per cell on each of "
             << limits.ranks << " rank(s); Geometry/Maximum cells sets it";
      limit.origin = origin.str();
      return limit;
    }

    ContainmentLimits meshing_containment(const MeshingLimits &limits, const SizeLimit &size)
    {
      ContainmentLimits containment;
      containment.seconds        = static_cast<unsigned int>(limits.seconds > 0 ? std::ceil(limits.seconds) :
                                                                                  seconds_before_estimate);
      containment.initial_memory = memory_before_estimate;
      // Once the estimate passes: what the largest allowed mesh needs, at most half of what the
      // machine has available (the ranks, and anything else running, keep the rest).
      const double available = available_memory();
      double       memory    = memory_before_estimate + child_bytes_per_cell * size.maximum_cells;
      if (available > 0)
        memory = std::min(memory, std::max(available / 2, static_cast<double>(memory_before_estimate)));
      containment.memory = size.maximum_cells > 0 || available > 0 ? static_cast<std::uint64_t>(memory) : 0;
      return containment;
    }

    // Refuses an estimate beyond the limit, with the parameters that asked for it.
    void check_estimate(const CellEstimate &estimate, const SizeLimit &limit, const std::string &file,
                        const std::map<std::string, double> &parameters)
    {
      if (limit.maximum_cells > 0 && estimate.cells > static_cast<double>(limit.maximum_cells))
        {
          std::ostringstream message;
          message.precision(3);
          message << "the mesh of " << describe(file, parameters) << " would have about " << estimate.cells
                  << " cells (estimated from " << estimate.basis << "), more than the " << limit.maximum_cells
                  << " allowed (" << limit.origin << "): check the geometry parameters (a length in the "
                  << "wrong unit asks for far more cells) or raise Geometry/Maximum cells";
          throw std::runtime_error(message.str());
        }
    }

    std::vector<GeometryParameter> read_geometry_parameters_unguarded(const std::string &file)
    {
      GmshSession session;
      open_or_throw(file);
      std::vector<std::string> names;
      gmsh::onelab::getNames(names, parameter_prefix + ".*");
      std::vector<GeometryParameter> parameters;
      for (const auto &full_name : names)
        {
          std::vector<double> value;
          gmsh::onelab::getNumber(full_name, value);
          if (value.empty())
            continue; // a string parameter: not ours
          parameters.push_back(
            {full_name.substr(parameter_prefix.size()), value[0], help_of(full_name)});
        }
      return parameters;
    }

    void generate_or_throw(const std::string &file, const int dimension)
    {
      try
        {
          gmsh::model::mesh::generate(dimension);
        }
      catch (...)
        {
          throw std::runtime_error("gmsh failed to mesh '" + file + "'");
        }
      throw_if_gmsh_error(file, "mesh");
    }

    // Meshes a .geo dimension by dimension, estimating its cells before each costlier stage and
    // refusing it there if it would exceed the limit; once an estimate passes, the child may take
    // the memory (and, by default, the time) a mesh of that size needs.
    void generate_guarded(const std::string &file, const std::map<std::string, double> &parameters,
                          const int dimension, const SizeLimit &limit)
    {
      const auto pass = [&](const CellEstimate &estimate) {
        check_estimate(estimate, limit, file, parameters);
        extend_contained_limits(limit.automatic_time ? static_cast<unsigned int>(std::ceil(
                                                         seconds_before_estimate + seconds_per_cell * estimate.cells)) :
                                                       0);
        return estimate;
      };
      const MeshConstraints constraints = read_mesh_constraints();
      check_estimate(estimate_cells_before_meshing(dimension, constraints), limit, file, parameters);
      set_contained_stage("meshing the curves");
      generate_or_throw(file, 1);
      CellEstimate estimate = pass(estimate_cells_from_curves(dimension, constraints));
      if (dimension == 3)
        {
          set_contained_stage("meshing the surfaces");
          generate_or_throw(file, 2);
          estimate = pass(estimate_cells_from_surfaces(constraints));
          // Tetrahedra meshed on the surface mesh of an earlier call differ from those of one
          // generate(3) (535 against 537 cells for thick_cylinder_3d.geo, quads = 0, nr = 4):
          // start again, so that the mesh is the one gmsh has always made. Meshing the curves
          // first is harmless (all 31 shipped .geo files mesh to the same text either way).
          gmsh::model::mesh::clear();
        }
      set_contained_stage(dimension == 3 ? "meshing the volumes" : "meshing the surfaces");
      generate_or_throw(file, dimension);
      if (std::getenv("COMPLIANT_MESH_ESTIMATE")) // checks of the estimate against the real count
        {
          std::vector<std::size_t> tags, nodes;
          std::size_t              cells = 0;
          std::vector<int>         types;
          std::vector<std::vector<std::size_t>> element_tags, element_nodes;
          gmsh::model::mesh::getElements(types, element_tags, element_nodes, dimension);
          for (const auto &t : element_tags)
            cells += t.size();
          std::fprintf(stderr, "mesh size estimate: %s: %.0f cells from %s, %zu meshed\n", file.c_str(),
                       estimate.cells, estimate.basis.c_str(), cells);
        }
    }

    void read_physical_groups(const std::string &file, MeshedGeometry &result)
    {
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups);
      for (const auto &[dim, tag] : groups)
        {
          std::string name;
          gmsh::model::getPhysicalName(dim, tag, name);
          if (name.empty())
            name = std::to_string(tag); // unnamed groups are addressed by number
          if (dim == result.dimension - 1)
            result.boundary_ids[name] = tag;
          else if (dim == result.dimension)
            result.material_ids[name] = tag;
        }
      if (result.material_ids.empty())
        throw std::runtime_error("geometry file '" + file + "' has no physical group of dimension " +
                                 std::to_string(result.dimension) +
                                 ": name the body (e.g. Physical Surface(\"body\") = {...};)");
    }

    // Gmsh 2.2 ASCII through a private temporary file; the text is what the ranks share.
    std::string msh_text()
    {
      char      tmp_name[] = "/tmp/compliant-mesh-XXXXXX.msh";
      const int fd         = mkstemps(tmp_name, 4);
      if (fd < 0)
        throw std::runtime_error("cannot create a temporary file for the mesh");
      close(fd);
      gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
      gmsh::option::setNumber("Mesh.SaveAll", 0);
      gmsh::option::setNumber("Mesh.Binary", 0);
      gmsh::write(tmp_name);
      std::ifstream      in(tmp_name);
      std::ostringstream text;
      text << in.rdbuf();
      std::remove(tmp_name);
      return text.str();
    }

    MeshedGeometry mesh_geometry_unguarded(const std::string &file, const std::map<std::string, double> &parameters,
                                           const SizeLimit &limit)
    {
      GmshSession session;
      for (const auto &[name, value] : parameters)
        gmsh::onelab::setNumber(parameter_prefix + name, {value});
      open_or_throw(file);
      throw_if_gmsh_error(file, "build the geometry of");

      MeshedGeometry result;
      result.dimension = gmsh::model::getDimension();
      if (result.dimension < 2)
        throw std::runtime_error("geometry file '" + file + "' has no surface or volume");
      if (is_geo(file))
        generate_guarded(file, parameters, result.dimension, limit);
      read_physical_groups(file, result);

      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh::model::mesh::getElements(types, tags, nodes, result.dimension);
      for (const auto &t : tags)
        result.n_cells += t.size();
      if (types.size() > 1)
        throw std::runtime_error("geometry file '" + file +
                                 "' mixes element types; use all quadrilaterals/hexahedra "
                                 "(Recombine + Transfinite) or all triangles/tetrahedra");
      // A ready .msh is not estimated but counted.
      check_estimate({static_cast<double>(result.n_cells), "the mesh file"}, limit, file, parameters);
      // After the count: a mesh beyond the limit is refused before its faces are read.
      set_contained_stage("checking the boundary groups");
      refuse_interior_boundaries(file, result);

      set_contained_stage("finding the curved boundaries");
      result.curved = find_curved_entities(result.dimension);
      set_contained_stage("writing the mesh");
      result.msh_text = msh_text();
      return result;
    }
  } // namespace

  std::vector<GeometryParameter> read_geometry_parameters(const std::string &file, const double seconds)
  {
    if (has_extension(file, ".inp"))
      return {}; // a ready mesh: no parameters
    ContainmentLimits containment;
    containment.memory  = memory_before_estimate;
    containment.seconds = static_cast<unsigned int>(seconds > 0 ? std::ceil(seconds) : seconds_before_estimate);
    try
      {
        return unpack_from_string<std::vector<GeometryParameter>>(call_contained(
          [&] {
            set_contained_stage("reading the geometry");
            return pack_to_string(with_gmsh_errors(file, [&] { return read_geometry_parameters_unguarded(file); }));
          },
          containment));
      }
    catch (const ContainedCallFailed &failure)
      {
        throw child_failure(failure, file, {});
      }
  }

  MeshedGeometry mesh_geometry(const std::string &file, const std::map<std::string, double> &parameters,
                               const MeshingLimits &limits)
  {
    if (has_extension(file, ".inp"))
      return read_abaqus_mesh(file);
    const SizeLimit size = resolve_size_limit(limits);
    try
      {
        return unpack_from_string<MeshedGeometry>(call_contained(
          [&] {
            set_contained_stage("reading the geometry");
            return pack_to_string(
              with_gmsh_errors(file, [&] { return mesh_geometry_unguarded(file, parameters, size); }));
          },
          meshing_containment(limits, size)));
      }
    catch (const ContainedCallFailed &failure)
      {
        throw child_failure(failure, file, parameters);
      }
  }

} // namespace compliant
