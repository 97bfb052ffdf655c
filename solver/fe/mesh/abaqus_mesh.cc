#include "mesh/abaqus_mesh.h"

#include "mesh/abaqus_deck.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace compliant
{
  namespace
  {
    using abaqus::Element;
    using abaqus::face_table;
    using abaqus::upper;
    using FaceKey = std::vector<long>; // a face's corner nodes, sorted

    std::vector<long> face_of(const Element &e, const int f)
    {
      std::vector<long> corners;
      for (const int local : face_table(e.kind.gmsh_type)[f])
        corners.push_back(e.nodes[local]);
      return corners;
    }

    FaceKey key_of(std::vector<long> corners)
    {
      std::sort(corners.begin(), corners.end());
      return corners;
    }

    // A read deck turned into the Gmsh text and physical names of MeshedGeometry, one step per
    // function, run in the order their checks throw. The deck is not const: its names are looked
    // up with operator[], as they always were.
    class GmshConversion
    {
    public:
      GmshConversion(abaqus::Deck &deck, const std::string &file)
        : deck(deck)
        , file(file)
      {}

      MeshedGeometry run();

    private:
      using Candidates = std::map<FaceKey, std::vector<std::string>>;

      void        check_cells();
      void        assign_element_groups();
      void        count_body_faces();
      Candidates  face_candidates();
      void        add_surface_candidates(Candidates &candidates);
      void        choose_face_groups(const Candidates &candidates);
      void        assign_tags();
      void        write_msh();
      std::string body_name(std::size_t i);

      abaqus::Deck                                         &deck;
      const std::string                                     file;
      int                                                   dimension = 0, body_type = 0;
      std::vector<std::string>                              body_group, boundary_element_group;
      std::map<FaceKey, std::pair<std::vector<long>, int>> faces; // oriented corners, count
      std::map<FaceKey, std::string>                        face_group;
      MeshedGeometry                                        result;
    };

    MeshedGeometry GmshConversion::run()
    {
      check_cells();
      result.dimension = dimension;
      assign_element_groups();
      count_body_faces();
      choose_face_groups(face_candidates());
      assign_tags();
      write_msh();
      return result;
    }

    // Body cells: the highest dimension; one cell type; every node defined.
    void GmshConversion::check_cells()
    {
      const auto &elements = deck.elements;
      for (const auto &e : elements)
        dimension = std::max(dimension, e.kind.dimension);
      if (dimension < 2)
        throw std::runtime_error("mesh file '" + file + "' has only line elements; expected a 2D or 3D body");
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
          if (!deck.nodes.count(n))
            throw std::runtime_error("mesh file '" + file + "', line " + std::to_string(e.line) + ": element " +
                                     std::to_string(e.id) + " uses node " + std::to_string(n) +
                                     ", which no *NODE defines");
    }

    // One body group per cell: the element set of its *SOLID SECTION (where the deck assigns a
    // material), else the smallest *ELSET holding it that no *SURFACE uses, else any other set;
    // cells in no set form the group "unnamed". Lower-dimensional elements pick a group alike.
    void GmshConversion::assign_element_groups()
    {
      const auto &elements = deck.elements;
      const auto set_rank  = [&](const std::string &name, const std::size_t size) {
        const int kind = deck.section_elsets.count(name) ? 0 :
                         deck.elset_explicit[name] ? (deck.surface_elsets.count(name) ? 2 : 1) : 3;
        return std::make_tuple(kind, size,
                               std::find(deck.elset_order.begin(), deck.elset_order.end(), name) -
                                 deck.elset_order.begin());
      };
      body_group.assign(elements.size(), "");
      boundary_element_group.assign(elements.size(), "");
      std::map<std::string, std::size_t> body_size, lower_size;
      for (const auto &[name, members] : deck.elsets)
        for (const long id : members)
          {
            const auto it = deck.element_index.find(id);
            if (it == deck.element_index.end())
              throw std::runtime_error("mesh file '" + file + "': element set '" + deck.display_name[name] +
                                       "' names element " + std::to_string(id) + ", which no *ELEMENT defines");
            ++(elements[it->second].kind.dimension == dimension ? body_size : lower_size)[name];
          }
      for (const auto &[name, members] : deck.elsets)
        for (const long id : members)
          {
            const std::size_t i       = deck.element_index.at(id);
            const bool        body    = elements[i].kind.dimension == dimension;
            auto             &current = body ? body_group[i] : boundary_element_group[i];
            const auto       &sizes   = body ? body_size : lower_size;
            if (current.empty() || set_rank(name, sizes.at(name)) < set_rank(current, sizes.at(current)))
              current = name;
          }
    }

    // Faces of the body cells by their sorted corners: a face counted once is on the boundary.
    void GmshConversion::count_body_faces()
    {
      for (const auto &e : deck.elements)
        if (e.kind.dimension == dimension)
          for (std::size_t f = 0; f < face_table(e.kind.gmsh_type).size(); ++f)
            {
              auto corners = face_of(e, static_cast<int>(f));
              auto &entry  = faces[key_of(corners)];
              entry.first  = corners;
              ++entry.second;
            }
    }

    // Candidate groups of each boundary face: lower-dimensional elements in a set, *SURFACE
    // faces, then node sets holding all its corners.
    GmshConversion::Candidates GmshConversion::face_candidates()
    {
      Candidates candidates;
      const auto on_boundary = [&](const FaceKey &key) {
        const auto it = faces.find(key);
        return it != faces.end() && it->second.second == 1;
      };
      const auto &elements = deck.elements;
      for (std::size_t i = 0; i < elements.size(); ++i)
        if (elements[i].kind.dimension == dimension - 1 && !boundary_element_group[i].empty())
          {
            const auto key = key_of(elements[i].nodes);
            if (on_boundary(key))
              candidates[key].push_back(boundary_element_group[i]);
          }
      add_surface_candidates(candidates);
      for (const auto &name : deck.nset_order)
        {
          const std::set<long> members(deck.nsets[name].begin(), deck.nsets[name].end());
          for (const auto &[key, entry] : faces)
            if (entry.second == 1 &&
                std::all_of(key.begin(), key.end(), [&](const long n) { return members.count(n) > 0; }))
              candidates[key].push_back(name);
        }
      return candidates;
    }

    // A *SURFACE line names an element or an element set, and a face of each of its cells.
    void GmshConversion::add_surface_candidates(Candidates &candidates)
    {
      for (const auto &name : deck.surface_order)
        for (const auto &[target, face] : deck.surfaces[name])
          {
            std::vector<long> ids;
            if (std::isalpha(static_cast<unsigned char>(target[0])) || target[0] == '_')
              {
                const auto set = deck.elsets.find(upper(target));
                if (set == deck.elsets.end())
                  throw std::runtime_error("mesh file '" + file + "': surface '" + deck.display_name[name] +
                                           "' names element set '" + target + "', which is not defined");
                ids = set->second;
              }
            else
              ids.push_back(std::strtol(target.c_str(), nullptr, 10));
            for (const long id : ids)
              {
                const auto it = deck.element_index.find(id);
                if (it == deck.element_index.end() || deck.elements[it->second].kind.dimension != dimension)
                  throw std::runtime_error("mesh file '" + file + "': surface '" + deck.display_name[name] +
                                           "' names element " + std::to_string(id) + ", which is not a body cell");
                const auto &e = deck.elements[it->second];
                if (face > static_cast<int>(face_table(e.kind.gmsh_type).size()))
                  throw std::runtime_error("mesh file '" + file + "': surface '" + deck.display_name[name] +
                                           "' names face S" + std::to_string(face) + " of element " +
                                           std::to_string(id) + ", which has " +
                                           std::to_string(face_table(e.kind.gmsh_type).size()));
                candidates[key_of(face_of(e, face - 1))].push_back(name);
              }
          }
    }

    // A face in several groups goes to the group with the fewest faces.
    void GmshConversion::choose_face_groups(const Candidates &candidates)
    {
      std::map<std::string, std::size_t> group_size;
      for (const auto &[key, names] : candidates)
        for (const auto &name : std::set<std::string>(names.begin(), names.end()))
          ++group_size[name];
      for (const auto &[key, names] : candidates)
        face_group[key] = *std::min_element(names.begin(), names.end(), [&](const std::string &a, const std::string &b) {
          return group_size[a] < group_size[b];
        });
    }

    std::string GmshConversion::body_name(const std::size_t i)
    {
      return body_group[i].empty() ? "unnamed" : deck.display_name[body_group[i]];
    }

    // Tags: boundary groups first (deal.II gives unnamed boundary faces id 0), then bodies.
    void GmshConversion::assign_tags()
    {
      int next_tag = 1;
      for (const auto &[key, name] : face_group)
        if (!result.boundary_ids.count(deck.display_name[name]))
          result.boundary_ids[deck.display_name[name]] = next_tag++;
      for (std::size_t i = 0; i < deck.elements.size(); ++i)
        if (deck.elements[i].kind.dimension == dimension)
          {
            const std::string name = body_name(i);
            if (!result.material_ids.count(name))
              result.material_ids[name] = next_tag++;
          }
    }

    // Gmsh 2.2 text: the body's nodes renumbered from 1, boundary faces, then cells.
    void GmshConversion::write_msh()
    {
      const auto          &elements = deck.elements;
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
          const auto &x = deck.nodes.at(id);
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
          const int tag = result.boundary_ids.at(deck.display_name[name]);
          msh << element_number++ << ' ' << face_type << " 2 " << tag << ' ' << tag;
          for (const long n : faces.at(key).first)
            msh << ' ' << renumbered.at(n);
          msh << '\n';
        }
      for (std::size_t i = 0; i < elements.size(); ++i)
        if (elements[i].kind.dimension == dimension)
          {
            const int tag = result.material_ids.at(body_name(i));
            msh << element_number++ << ' ' << body_type << " 2 " << tag << ' ' << tag;
            for (const long n : elements[i].nodes)
              msh << ' ' << renumbered.at(n);
            msh << '\n';
          }
      msh << "$EndElements\n";
      result.msh_text = msh.str();
      result.n_cells  = n_cells;
    }
  } // namespace

  MeshedGeometry read_abaqus_mesh(const std::string &file)
  {
    abaqus::Deck deck = abaqus::read_deck(file);
    return GmshConversion(deck, file).run();
  }
} // namespace compliant
