#include "mesh/abaqus_mesh.h"

#include <text/text_utilities.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <stdexcept>
#include <vector>

namespace compliant
{
  namespace
  {
    struct ElementKind
    {
      int dimension;   // 1, 2, 3
      int n_nodes;     // nodes on a data line
      int n_corners;   // leading corner nodes (the rest are mid-side nodes)
      int gmsh_type;   // Gmsh element type of the corner element
    };

    // Abaqus/CalculiX element names: the first letters and the node count decide.
    bool element_kind(const std::string &type, ElementKind &kind)
    {
      const auto starts = [&](const char *prefix) { return type.rfind(prefix, 0) == 0; };
      const auto digits = [&](std::size_t from) {
        int n = 0;
        for (std::size_t i = from; i < type.size() && std::isdigit(static_cast<unsigned char>(type[i])); ++i)
          n = 10 * n + (type[i] - '0');
        return n;
      };
      if (starts("C3D"))
        {
          const int n = digits(3);
          if (n == 4 || n == 10)
            return kind = {3, n, 4, 4}, true;
          if (n == 8 || n == 20)
            return kind = {3, n, 8, 5}, true;
          return false; // wedges (C3D6, C3D15), 27-node bricks
        }
      int n = 0;
      if (starts("CPS") || starts("CPE") || starts("CAX"))
        n = digits(3);
      else if (starts("M3D"))
        n = digits(3);
      else if (starts("S") && type.size() > 1 && std::isdigit(static_cast<unsigned char>(type[1])))
        n = digits(1);
      else if (starts("T2D") || starts("T3D") || starts("B2") || starts("B3"))
        {
          const int m = starts("B") ? (type.size() > 2 && type[2] == '2' ? 3 : 2) : digits(3);
          return kind = {1, m, 2, 1}, (m == 2 || m == 3);
        }
      if (n == 3 || n == 6)
        return kind = {2, n, 3, 2}, true;
      if (n == 4 || n == 8)
        return kind = {2, n, 4, 3}, true;
      return false;
    }

    // Faces of a body cell by its corner nodes (Abaqus S1, S2, ... in order: Abaqus and Gmsh
    // number corners alike for these cells).
    const std::vector<std::vector<int>> &face_table(const int gmsh_type)
    {
      static const std::vector<std::vector<int>> triangle = {{0, 1}, {1, 2}, {2, 0}};
      static const std::vector<std::vector<int>> quadrilateral = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
      static const std::vector<std::vector<int>> tetrahedron = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
      static const std::vector<std::vector<int>> hexahedron = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1},
                                                               {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
      static const std::vector<std::vector<int>> none;
      switch (gmsh_type)
        {
          case 2: return triangle;
          case 3: return quadrilateral;
          case 4: return tetrahedron;
          case 5: return hexahedron;
          default: return none;
        }
    }

    std::string upper(std::string text)
    {
      for (auto &c : text)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      return text;
    }

    using text::trim;
    std::vector<std::string> split(const std::string &line) { return text::split_trimmed(line, ','); }

    struct Element
    {
      long              id;
      ElementKind       kind;
      std::vector<long> nodes;
      std::size_t       line;
    };

    struct Reader
    {
      std::string file;
      std::size_t line_number = 0;

      [[noreturn]] void fail(const std::string &what) const
      {
        throw std::runtime_error("'" + file + "', line " + std::to_string(line_number) + ": " + what);
      }

      long integer(const std::string &text, const char *what) const
      {
        errno = 0;
        char      *end   = nullptr;
        const long value = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || *end != '\0' || errno != 0)
          fail("expected " + std::string(what) + " (an integer), got '" + text + "'");
        return value;
      }

      double number(const std::string &text) const
      {
        errno = 0;
        char        *end   = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(value))
          fail("expected a coordinate (a finite number), got '" + text + "'");
        return value;
      }
    };

    // "NAME=value" parameters of a keyword line, upper-cased names, values as written.
    std::map<std::string, std::string> keyword_parameters(const std::vector<std::string> &fields)
    {
      std::map<std::string, std::string> parameters;
      for (std::size_t i = 1; i < fields.size(); ++i)
        {
          const auto eq = fields[i].find('=');
          if (eq == std::string::npos)
            parameters[upper(fields[i])] = "";
          else
            parameters[upper(trim(fields[i].substr(0, eq)))] = trim(fields[i].substr(eq + 1));
        }
      return parameters;
    }
  } // namespace

  MeshedGeometry read_abaqus_mesh(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("mesh file '" + file + "' does not exist or cannot be read");
    Reader reader{file};

    std::map<long, std::array<double, 3>>        nodes;
    std::vector<Element>                         elements;
    std::map<long, std::size_t>                  element_index;
    // Sets in definition order: names (upper case, as Abaqus compares them) and members.
    std::vector<std::string>                     elset_order, nset_order, surface_order;
    std::map<std::string, std::vector<long>>     elsets, nsets;
    std::map<std::string, bool>                  elset_explicit; // *ELSET (not ELSET= of *ELEMENT)
    std::set<std::string>                        section_elsets; // ELSET= of *SOLID/*SHELL SECTION
    std::set<std::string>                        surface_elsets; // named in *SURFACE lines
    std::map<std::string, std::vector<std::pair<std::string, int>>> surfaces; // element or elset, face
    std::map<std::string, std::string>           display_name;

    enum class Block { none, node, element, elset, nset, surface, skip };
    Block                    block = Block::none;
    std::string              set_name, element_type;
    ElementKind              kind{};
    bool                     generate = false;
    std::vector<std::string> pending; // an element's fields across continuation lines
    std::size_t              pending_line = 0;

    const auto remember = [&](std::vector<std::string> &order, const std::string &name) {
      const std::string key = upper(name);
      if (std::find(order.begin(), order.end(), key) == order.end())
        order.push_back(key);
      display_name.emplace(key, name);
      return key;
    };
    const auto add_ids = [&](std::vector<long> &members, const std::vector<std::string> &fields,
                             const std::map<std::string, std::vector<long>> &named) {
      if (generate)
        {
          if (fields.size() < 2 || fields.size() > 3)
            reader.fail("GENERATE expects 'first, last[, step]'");
          const long first = reader.integer(fields[0], "the first id"), last = reader.integer(fields[1], "the last id");
          const long step  = fields.size() == 3 && !fields[2].empty() ? reader.integer(fields[2], "the step") : 1;
          if (step <= 0 || last < first || (last - first) / step > 100000000)
            reader.fail("GENERATE expects first <= last and a positive step");
          for (long id = first; id <= last; id += step)
            members.push_back(id);
          return;
        }
      for (const auto &field : fields)
        {
          if (field.empty())
            continue;
          if (std::isalpha(static_cast<unsigned char>(field[0])) || field[0] == '_')
            {
              const auto other = named.find(upper(field));
              if (other == named.end())
                reader.fail("set '" + field + "' is not defined before it is used");
              members.insert(members.end(), other->second.begin(), other->second.end());
            }
          else
            members.push_back(reader.integer(field, "an id"));
        }
    };

    std::string raw;
    while (std::getline(in, raw))
      {
        ++reader.line_number;
        const std::string line = trim(raw);
        if (line.empty() || line.rfind("**", 0) == 0)
          continue;
        if (line[0] == '*')
          {
            if (!pending.empty())
              {
                reader.line_number = pending_line;
                reader.fail("element with " + std::to_string(pending.size() - 1) + " nodes; " + element_type +
                            " needs " + std::to_string(kind.n_nodes));
              }
            const auto fields     = split(line);
            const auto keyword    = upper(fields[0]);
            const auto parameters = keyword_parameters(fields);
            generate              = parameters.count("GENERATE") > 0;
            block                 = Block::skip;
            if (keyword == "*NODE")
              {
                block    = Block::node;
                set_name = parameters.count("NSET") ? remember(nset_order, parameters.at("NSET")) : "";
              }
            else if (keyword == "*ELEMENT")
              {
                if (!parameters.count("TYPE"))
                  reader.fail("*ELEMENT without TYPE=");
                element_type = upper(parameters.at("TYPE"));
                if (!element_kind(element_type, kind))
                  reader.fail("element type " + element_type + " is not supported; expected C3D4, C3D10, C3D8, "
                              "C3D20 (R/I/H), CPS/CPE/CAX/S/M3D 3, 4, 6 or 8, or T2D2/T3D2/B21/B31");
                block    = Block::element;
                set_name = "";
                if (parameters.count("ELSET"))
                  {
                    set_name = remember(elset_order, parameters.at("ELSET"));
                    elset_explicit.emplace(set_name, false);
                  }
              }
            else if (keyword == "*ELSET" || keyword == "*NSET")
              {
                const std::string key = keyword == "*ELSET" ? "ELSET" : "NSET";
                if (!parameters.count(key) || parameters.at(key).empty())
                  reader.fail(keyword + " without " + key + "=");
                block = keyword == "*ELSET" ? Block::elset : Block::nset;
                set_name = remember(keyword == "*ELSET" ? elset_order : nset_order, parameters.at(key));
                if (block == Block::elset)
                  elset_explicit[set_name] = true;
              }
            else if ((keyword == "*SOLID SECTION" || keyword == "*SHELL SECTION") && parameters.count("ELSET"))
              section_elsets.insert(upper(parameters.at("ELSET")));
            else if (keyword == "*SURFACE")
              {
                if (!parameters.count("NAME") || parameters.at("NAME").empty())
                  reader.fail("*SURFACE without NAME=");
                const bool node_surface = parameters.count("TYPE") && upper(parameters.at("TYPE")) == "NODE";
                if (node_surface) // a node-based surface reads like a node set
                  block = Block::nset, set_name = remember(nset_order, parameters.at("NAME"));
                else
                  block = Block::surface, set_name = remember(surface_order, parameters.at("NAME"));
              }
            continue;
          }

        const auto fields = split(line);
        switch (block)
          {
            case Block::none:
              reader.fail("data before any keyword; an .inp file starts with *HEADING or *NODE");
            case Block::skip:
              break;
            case Block::node:
              {
                if (fields.size() < 3 || fields.size() > 4)
                  reader.fail("a node line is 'id, x, y[, z]'");
                const long id = reader.integer(fields[0], "a node id");
                std::array<double, 3> x{{0, 0, 0}};
                for (std::size_t d = 1; d < fields.size(); ++d)
                  x[d - 1] = reader.number(fields[d]);
                if (!nodes.emplace(id, x).second)
                  reader.fail("node " + std::to_string(id) + " is defined twice");
                if (!set_name.empty())
                  nsets[set_name].push_back(id);
                break;
              }
            case Block::element:
              {
                if (pending.empty())
                  pending_line = reader.line_number;
                for (const auto &f : fields)
                  if (!f.empty())
                    pending.push_back(f);
                if (pending.size() < static_cast<std::size_t>(kind.n_nodes) + 1)
                  break; // continued on the next line
                if (pending.size() > static_cast<std::size_t>(kind.n_nodes) + 1)
                  reader.fail("element with " + std::to_string(pending.size() - 1) + " nodes; " + element_type +
                              " has " + std::to_string(kind.n_nodes));
                Element element{reader.integer(pending[0], "an element id"), kind, {}, pending_line};
                for (int i = 1; i <= kind.n_corners; ++i)
                  element.nodes.push_back(reader.integer(pending[i], "a node id"));
                pending.clear();
                if (!element_index.emplace(element.id, elements.size()).second)
                  reader.fail("element " + std::to_string(element.id) + " is defined twice");
                if (!set_name.empty())
                  elsets[set_name].push_back(element.id);
                elements.push_back(std::move(element));
                break;
              }
            case Block::elset:
              add_ids(elsets[set_name], fields, elsets);
              break;
            case Block::nset:
              {
                // A node-based *SURFACE line may carry a weight (a decimal number): not an id.
                std::vector<std::string> ids;
                for (const auto &f : fields)
                  if (generate || f.find('.') == std::string::npos)
                    ids.push_back(f);
                add_ids(nsets[set_name], ids, nsets);
                break;
              }
            case Block::surface:
              {
                if (fields.size() != 2 || upper(fields[1]).size() < 2 || upper(fields[1])[0] != 'S')
                  reader.fail("a surface line is 'element or element set, S<face>'");
                const int face = static_cast<int>(reader.integer(upper(fields[1]).substr(1), "a face number"));
                if (face < 1 || face > 6)
                  reader.fail("face S" + std::to_string(face) + " does not exist; faces are S1 to S6");
                surfaces[set_name].emplace_back(fields[0], face);
                surface_elsets.insert(upper(fields[0]));
                break;
              }
          }
      }
    if (!pending.empty())
      {
        reader.line_number = pending_line;
        reader.fail("element line ends before its " + std::to_string(kind.n_nodes) + " nodes");
      }
    if (elements.empty())
      throw std::runtime_error("mesh file '" + file + "' has no *ELEMENT data");

    // Body cells: the highest dimension; one cell type.
    int dimension = 0;
    for (const auto &e : elements)
      dimension = std::max(dimension, e.kind.dimension);
    if (dimension < 2)
      throw std::runtime_error("mesh file '" + file + "' has only line elements; expected a 2D or 3D body");
    int body_type = 0;
    for (const auto &e : elements)
      if (e.kind.dimension == dimension)
        {
          if (body_type != 0 && e.kind.gmsh_type != body_type)
            throw std::runtime_error("mesh file '" + file + "', line " + std::to_string(e.line) +
                                     ": mixes cell types; use all quadrilaterals/hexahedra or all "
                                     "triangles/tetrahedra");
          body_type = e.kind.gmsh_type;
        }
    for (const auto &e : elements)
      for (const long n : e.nodes)
        if (!nodes.count(n))
          throw std::runtime_error("mesh file '" + file + "', line " + std::to_string(e.line) + ": element " +
                                   std::to_string(e.id) + " uses node " + std::to_string(n) +
                                   ", which no *NODE defines");

    MeshedGeometry result;
    result.dimension = dimension;

    // One body group per cell: the element set of its *SOLID SECTION (where the deck assigns a
    // material), else the smallest *ELSET holding it that no *SURFACE uses, else any other set;
    // cells in no set form the group "unnamed".
    const auto set_rank = [&](const std::string &name, const std::size_t size) {
      const int kind = section_elsets.count(name) ? 0 :
                       elset_explicit[name] ? (surface_elsets.count(name) ? 2 : 1) : 3;
      return std::make_tuple(kind, size,
                             std::find(elset_order.begin(), elset_order.end(), name) - elset_order.begin());
    };
    std::vector<std::string> body_group(elements.size());
    std::vector<std::string> boundary_element_group(elements.size());
    {
      std::map<std::string, std::size_t> body_size, lower_size;
      for (const auto &[name, members] : elsets)
        for (const long id : members)
          {
            const auto it = element_index.find(id);
            if (it == element_index.end())
              throw std::runtime_error("mesh file '" + file + "': element set '" + display_name[name] +
                                       "' names element " + std::to_string(id) + ", which no *ELEMENT defines");
            ++(elements[it->second].kind.dimension == dimension ? body_size : lower_size)[name];
          }
      for (const auto &[name, members] : elsets)
        for (const long id : members)
          {
            const std::size_t i       = element_index.at(id);
            const bool        body    = elements[i].kind.dimension == dimension;
            auto             &current = body ? body_group[i] : boundary_element_group[i];
            const auto       &sizes   = body ? body_size : lower_size;
            if (current.empty() || set_rank(name, sizes.at(name)) < set_rank(current, sizes.at(current)))
              current = name;
          }
    }

    // Boundary faces of the body, by their sorted corner nodes.
    using FaceKey = std::vector<long>;
    std::map<FaceKey, std::pair<std::vector<long>, int>> faces; // oriented corners, count
    const auto face_of = [&](const Element &e, const int f) {
      std::vector<long> corners;
      for (const int local : face_table(e.kind.gmsh_type)[f])
        corners.push_back(e.nodes[local]);
      return corners;
    };
    const auto key_of = [](std::vector<long> corners) {
      std::sort(corners.begin(), corners.end());
      return corners;
    };
    for (const auto &e : elements)
      if (e.kind.dimension == dimension)
        for (std::size_t f = 0; f < face_table(e.kind.gmsh_type).size(); ++f)
          {
            auto corners = face_of(e, static_cast<int>(f));
            auto &entry  = faces[key_of(corners)];
            entry.first  = corners;
            ++entry.second;
          }

    // Candidate groups of each boundary face, then the smallest group wins.
    std::map<FaceKey, std::vector<std::string>> candidates;
    const auto on_boundary = [&](const FaceKey &key) {
      const auto it = faces.find(key);
      return it != faces.end() && it->second.second == 1;
    };
    for (std::size_t i = 0; i < elements.size(); ++i)
      if (elements[i].kind.dimension == dimension - 1 && !boundary_element_group[i].empty())
        {
          const auto key = key_of(elements[i].nodes);
          if (on_boundary(key))
            candidates[key].push_back(boundary_element_group[i]);
        }
    for (const auto &name : surface_order)
      for (const auto &[target, face] : surfaces[name])
        {
          std::vector<long> ids;
          if (std::isalpha(static_cast<unsigned char>(target[0])) || target[0] == '_')
            {
              const auto set = elsets.find(upper(target));
              if (set == elsets.end())
                throw std::runtime_error("mesh file '" + file + "': surface '" + display_name[name] +
                                         "' names element set '" + target + "', which is not defined");
              ids = set->second;
            }
          else
            ids.push_back(std::strtol(target.c_str(), nullptr, 10));
          for (const long id : ids)
            {
              const auto it = element_index.find(id);
              if (it == element_index.end() || elements[it->second].kind.dimension != dimension)
                throw std::runtime_error("mesh file '" + file + "': surface '" + display_name[name] +
                                         "' names element " + std::to_string(id) + ", which is not a body cell");
              const auto &e = elements[it->second];
              if (face > static_cast<int>(face_table(e.kind.gmsh_type).size()))
                throw std::runtime_error("mesh file '" + file + "': surface '" + display_name[name] + "' names face S" +
                                         std::to_string(face) + " of element " + std::to_string(id) + ", which has " +
                                         std::to_string(face_table(e.kind.gmsh_type).size()));
              candidates[key_of(face_of(e, face - 1))].push_back(name);
            }
        }
    for (const auto &name : nset_order)
      {
        const std::set<long> members(nsets[name].begin(), nsets[name].end());
        for (const auto &[key, entry] : faces)
          if (entry.second == 1 &&
              std::all_of(key.begin(), key.end(), [&](const long n) { return members.count(n) > 0; }))
            candidates[key].push_back(name);
      }
    std::map<std::string, std::size_t> group_size;
    for (const auto &[key, names] : candidates)
      for (const auto &name : std::set<std::string>(names.begin(), names.end()))
        ++group_size[name];
    std::map<FaceKey, std::string> face_group;
    for (const auto &[key, names] : candidates)
      face_group[key] = *std::min_element(names.begin(), names.end(), [&](const std::string &a, const std::string &b) {
        return group_size[a] < group_size[b];
      });

    // Tags: boundary groups first (deal.II gives unnamed boundary faces id 0), then bodies.
    int next_tag = 1;
    for (const auto &[key, name] : face_group)
      if (!result.boundary_ids.count(display_name[name]))
        result.boundary_ids[display_name[name]] = next_tag++;
    for (std::size_t i = 0; i < elements.size(); ++i)
      if (elements[i].kind.dimension == dimension)
        {
          const std::string name = body_group[i].empty() ? "unnamed" : display_name[body_group[i]];
          if (!result.material_ids.count(name))
            result.material_ids[name] = next_tag++;
        }

    // Gmsh 2.2 text: the body's nodes renumbered from 1, boundary faces, then cells.
    std::map<long, long> renumbered;
    for (const auto &e : elements)
      if (e.kind.dimension == dimension)
        for (const long n : e.nodes)
          renumbered.emplace(n, 0);
    long next_node = 1;
    for (auto &[id, number] : renumbered)
      number = next_node++;
    std::ostringstream msh;
    msh.precision(17);
    msh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << renumbered.size() << "\n";
    for (const auto &[id, number] : renumbered)
      {
        const auto &x = nodes.at(id);
        msh << number << ' ' << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
      }
    std::size_t n_cells = 0;
    for (const auto &e : elements)
      n_cells += e.kind.dimension == dimension;
    const int face_type = dimension == 2 ? 1 : (body_type == 4 ? 2 : 3);
    msh << "$EndNodes\n$Elements\n" << face_group.size() + n_cells << "\n";
    long element_number = 1;
    for (const auto &[key, name] : face_group)
      {
        const int tag = result.boundary_ids.at(display_name[name]);
        msh << element_number++ << ' ' << face_type << " 2 " << tag << ' ' << tag;
        for (const long n : faces.at(key).first)
          msh << ' ' << renumbered.at(n);
        msh << '\n';
      }
    for (std::size_t i = 0; i < elements.size(); ++i)
      if (elements[i].kind.dimension == dimension)
        {
          const int tag = result.material_ids.at(body_group[i].empty() ? "unnamed" : display_name[body_group[i]]);
          msh << element_number++ << ' ' << body_type << " 2 " << tag << ' ' << tag;
          for (const long n : elements[i].nodes)
            msh << ' ' << renumbered.at(n);
          msh << '\n';
        }
    msh << "$EndElements\n";
    result.msh_text = msh.str();
    result.n_cells  = n_cells;
    return result;
  }
} // namespace compliant
