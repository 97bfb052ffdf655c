#include "mesh/abaqus_deck.h"

#include <text/text_utilities.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace compliant
{
  namespace abaqus
  {
    namespace
    {
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

      using text::trim;
      std::vector<std::string> split(const std::string &line) { return text::split_trimmed(line, ','); }

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

      // Reads a deck line by line: a keyword line opens a block, and the data lines after it are
      // read as that block says. An element may run over several lines, so its fields wait in
      // `pending` until it has all its nodes.
      class DeckParser
      {
      public:
        explicit DeckParser(const std::string &file)
          : reader{file}
        {}

        void read_line(const std::string &raw);
        Deck finish();

      private:
        enum class Block { none, node, element, elset, nset, surface, skip };
        using Parameters = std::map<std::string, std::string>;

        void read_keyword(const std::string &line);
        void open_element_block(const Parameters &parameters);
        void read_data(const std::vector<std::string> &fields);
        void read_node(const std::vector<std::string> &fields);
        void read_element(const std::vector<std::string> &fields);
        void read_node_set(const std::vector<std::string> &fields);
        void read_surface(const std::vector<std::string> &fields);
        std::string remember(std::vector<std::string> &order, const std::string &name);
        void add_ids(std::vector<long> &members, const std::vector<std::string> &fields,
                     const std::map<std::string, std::vector<long>> &named) const;

        Reader                   reader;
        Deck                     deck;
        Block                    block = Block::none;
        std::string              set_name, element_type;
        ElementKind              kind{};
        bool                     generate = false;
        std::vector<std::string> pending; // an element's fields across continuation lines
        std::size_t              pending_line = 0;
      };

      void DeckParser::read_line(const std::string &raw)
      {
        ++reader.line_number;
        const std::string line = trim(raw);
        if (line.empty() || line.rfind("**", 0) == 0)
          return;
        if (line[0] == '*')
          read_keyword(line);
        else
          read_data(split(line));
      }

      void DeckParser::read_keyword(const std::string &line)
      {
        // A keyword ends the element before it: a short one is an error at its own line.
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
            set_name = parameters.count("NSET") ? remember(deck.nset_order, parameters.at("NSET")) : "";
          }
        else if (keyword == "*ELEMENT")
          open_element_block(parameters);
        else if (keyword == "*ELSET" || keyword == "*NSET")
          {
            const std::string key = keyword == "*ELSET" ? "ELSET" : "NSET";
            if (!parameters.count(key) || parameters.at(key).empty())
              reader.fail(keyword + " without " + key + "=");
            block = keyword == "*ELSET" ? Block::elset : Block::nset;
            set_name = remember(keyword == "*ELSET" ? deck.elset_order : deck.nset_order, parameters.at(key));
            if (block == Block::elset)
              deck.elset_explicit[set_name] = true;
          }
        else if ((keyword == "*SOLID SECTION" || keyword == "*SHELL SECTION") && parameters.count("ELSET"))
          deck.section_elsets.insert(upper(parameters.at("ELSET")));
        else if (keyword == "*SURFACE")
          {
            if (!parameters.count("NAME") || parameters.at("NAME").empty())
              reader.fail("*SURFACE without NAME=");
            const bool node_surface = parameters.count("TYPE") && upper(parameters.at("TYPE")) == "NODE";
            if (node_surface) // a node-based surface reads like a node set
              block = Block::nset, set_name = remember(deck.nset_order, parameters.at("NAME"));
            else
              block = Block::surface, set_name = remember(deck.surface_order, parameters.at("NAME"));
          }
      }

      void DeckParser::open_element_block(const Parameters &parameters)
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
            set_name = remember(deck.elset_order, parameters.at("ELSET"));
            deck.elset_explicit.emplace(set_name, false);
          }
      }

      void DeckParser::read_data(const std::vector<std::string> &fields)
      {
        switch (block)
          {
            case Block::none:
              reader.fail("data before any keyword; an .inp file starts with *HEADING or *NODE");
            case Block::skip:
              break;
            case Block::node:
              read_node(fields);
              break;
            case Block::element:
              read_element(fields);
              break;
            case Block::elset:
              add_ids(deck.elsets[set_name], fields, deck.elsets);
              break;
            case Block::nset:
              read_node_set(fields);
              break;
            case Block::surface:
              read_surface(fields);
              break;
          }
      }

      void DeckParser::read_node(const std::vector<std::string> &fields)
      {
        if (fields.size() < 3 || fields.size() > 4)
          reader.fail("a node line is 'id, x, y[, z]'");
        const long id = reader.integer(fields[0], "a node id");
        std::array<double, 3> x{{0, 0, 0}};
        for (std::size_t d = 1; d < fields.size(); ++d)
          x[d - 1] = reader.number(fields[d]);
        if (!deck.nodes.emplace(id, x).second)
          reader.fail("node " + std::to_string(id) + " is defined twice");
        if (!set_name.empty())
          deck.nsets[set_name].push_back(id);
      }

      void DeckParser::read_element(const std::vector<std::string> &fields)
      {
        if (pending.empty())
          pending_line = reader.line_number;
        for (const auto &f : fields)
          if (!f.empty())
            pending.push_back(f);
        if (pending.size() < static_cast<std::size_t>(kind.n_nodes) + 1)
          return; // continued on the next line
        if (pending.size() > static_cast<std::size_t>(kind.n_nodes) + 1)
          reader.fail("element with " + std::to_string(pending.size() - 1) + " nodes; " + element_type +
                      " has " + std::to_string(kind.n_nodes));
        Element element{reader.integer(pending[0], "an element id"), kind, {}, pending_line};
        for (int i = 1; i <= kind.n_corners; ++i)
          element.nodes.push_back(reader.integer(pending[i], "a node id"));
        pending.clear();
        if (!deck.element_index.emplace(element.id, deck.elements.size()).second)
          reader.fail("element " + std::to_string(element.id) + " is defined twice");
        if (!set_name.empty())
          deck.elsets[set_name].push_back(element.id);
        deck.elements.push_back(std::move(element));
      }

      void DeckParser::read_node_set(const std::vector<std::string> &fields)
      {
        // A node-based *SURFACE line may carry a weight (a decimal number): not an id.
        std::vector<std::string> ids;
        for (const auto &f : fields)
          if (generate || f.find('.') == std::string::npos)
            ids.push_back(f);
        add_ids(deck.nsets[set_name], ids, deck.nsets);
      }

      void DeckParser::read_surface(const std::vector<std::string> &fields)
      {
        if (fields.size() != 2 || upper(fields[1]).size() < 2 || upper(fields[1])[0] != 'S')
          reader.fail("a surface line is 'element or element set, S<face>'");
        const int face = static_cast<int>(reader.integer(upper(fields[1]).substr(1), "a face number"));
        if (face < 1 || face > 6)
          reader.fail("face S" + std::to_string(face) + " does not exist; faces are S1 to S6");
        deck.surfaces[set_name].emplace_back(fields[0], face);
        deck.surface_elsets.insert(upper(fields[0]));
      }

      // The upper-case key of a set name, kept once in definition order; the first spelling is
      // the one the case file sees.
      std::string DeckParser::remember(std::vector<std::string> &order, const std::string &name)
      {
        const std::string key = upper(name);
        if (std::find(order.begin(), order.end(), key) == order.end())
          order.push_back(key);
        deck.display_name.emplace(key, name);
        return key;
      }

      // Ids of a set line: a GENERATE range, or ids and names of sets defined before.
      void DeckParser::add_ids(std::vector<long> &members, const std::vector<std::string> &fields,
                               const std::map<std::string, std::vector<long>> &named) const
      {
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
      }

      Deck DeckParser::finish()
      {
        if (!pending.empty())
          {
            reader.line_number = pending_line;
            reader.fail("element line ends before its " + std::to_string(kind.n_nodes) + " nodes");
          }
        if (deck.elements.empty())
          throw std::runtime_error("mesh file '" + reader.file + "' has no *ELEMENT data");
        return std::move(deck);
      }
    } // namespace

    Deck read_deck(const std::string &file)
    {
      std::ifstream in(file);
      if (!in)
        throw std::runtime_error("mesh file '" + file + "' does not exist or cannot be read");
      DeckParser  parser(file);
      std::string raw;
      while (std::getline(in, raw))
        parser.read_line(raw);
      return parser.finish();
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
  } // namespace abaqus
} // namespace compliant
