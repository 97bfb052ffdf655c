#include "mesh/gmsh_geometry.h"

#include "mesh/abaqus_mesh.h"

#include <gmsh.h>

#include <cstdio>
#include <fstream>
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

  std::vector<GeometryParameter> read_geometry_parameters_unguarded(const std::string &file);
  MeshedGeometry mesh_geometry_unguarded(const std::string &file, const std::map<std::string, double> &parameters);

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
  } // namespace

  std::vector<GeometryParameter> read_geometry_parameters(const std::string &file)
  {
    if (has_extension(file, ".inp"))
      return {}; // a ready mesh: no parameters
    return with_gmsh_errors(file, [&] { return read_geometry_parameters_unguarded(file); });
  }

  MeshedGeometry mesh_geometry(const std::string &file, const std::map<std::string, double> &parameters)
  {
    if (has_extension(file, ".inp"))
      return read_abaqus_mesh(file);
    return with_gmsh_errors(file, [&] { return mesh_geometry_unguarded(file, parameters); });
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

  MeshedGeometry mesh_geometry_unguarded(const std::string &file,
                                         const std::map<std::string, double> &parameters)
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
      {
        try
          {
            gmsh::model::mesh::generate(result.dimension);
          }
        catch (...)
          {
            throw std::runtime_error("gmsh failed to mesh '" + file + "'");
          }
        throw_if_gmsh_error(file, "mesh");
      }

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

    std::vector<int>                      types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, result.dimension);
    for (const auto &t : tags)
      result.n_cells += t.size();
    if (types.size() > 1)
      throw std::runtime_error("geometry file '" + file +
                               "' mixes element types; use all quadrilaterals/hexahedra "
                               "(Recombine + Transfinite) or all triangles/tetrahedra");

    result.curved = find_curved_entities(result.dimension);

    // Gmsh 2.2 ASCII through a private temporary file; the text is what the ranks share.
    char tmp_name[] = "/tmp/compliant-mesh-XXXXXX.msh";
    const int fd    = mkstemps(tmp_name, 4);
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
    result.msh_text = text.str();
    return result;
  }
} // namespace compliant
