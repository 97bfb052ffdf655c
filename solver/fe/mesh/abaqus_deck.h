// The mesh part of an Abaqus/CalculiX input deck (.inp) as written: nodes, elements, element and
// node sets, element-face surfaces, and the set names a *SOLID/*SHELL SECTION or a *SURFACE line
// uses. read_abaqus_mesh (abaqus_mesh.h) turns it into Gmsh text; kept apart so that reading the
// deck and choosing the groups can be read (and kept within size) separately. Free of deal.II.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace compliant
{
  namespace abaqus
  {
    struct ElementKind
    {
      int dimension;   // 1, 2, 3
      int n_nodes;     // nodes on a data line
      int n_corners;   // leading corner nodes (the rest are mid-side nodes)
      int gmsh_type;   // Gmsh element type of the corner element
    };

    struct Element
    {
      long              id;
      ElementKind       kind;
      std::vector<long> nodes; // corner nodes only
      std::size_t       line;
    };

    struct Deck
    {
      std::map<long, std::array<double, 3>>    nodes;
      std::vector<Element>                     elements;
      std::map<long, std::size_t>              element_index;
      // Sets in definition order: names (upper case, as Abaqus compares them) and members.
      std::vector<std::string>                 elset_order, nset_order, surface_order;
      std::map<std::string, std::vector<long>> elsets, nsets;
      std::map<std::string, bool>              elset_explicit; // *ELSET (not ELSET= of *ELEMENT)
      std::set<std::string>                    section_elsets; // ELSET= of *SOLID/*SHELL SECTION
      std::set<std::string>                    surface_elsets; // named in *SURFACE lines
      std::map<std::string, std::vector<std::pair<std::string, int>>> surfaces; // element or elset, face
      std::map<std::string, std::string>       display_name; // upper-case name -> as first written
    };

    // Throws std::runtime_error naming the file and line on anything it cannot read; a deck
    // without elements is an error too.
    Deck read_deck(const std::string &file);

    // Corners of each face of a body cell of this Gmsh type, Abaqus face S1 first; empty for
    // other types.
    const std::vector<std::vector<int>> &face_table(int gmsh_type);

    std::string upper(std::string text);
  } // namespace abaqus
} // namespace compliant
