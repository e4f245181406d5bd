#include <fuzzycontact/scene/abaqus_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

namespace FuzzyContact
{
  namespace
  {
    std::string
    upper(std::string s)
    {
      std::transform(s.begin(), s.end(), s.begin(), [](const unsigned char c) {
        return static_cast<char>(std::toupper(c));
      });
      return s;
    }

    // A keyword line "*Elset, elset=Steel, generate": its keyword
    // ("ELSET") and its parameters (upper-case keys; values as written).
    struct Keyword
    {
      std::string                        name;
      std::map<std::string, std::string> parameters;

      explicit Keyword(const std::string &line)
      {
        const std::vector<std::string> items =
          Utilities::split_string_list(line.substr(1), ',');
        name = items.empty() ? "" : upper(items[0]);
        for (unsigned int i = 1; i < items.size(); ++i)
          {
            const auto equals = items[i].find('=');
            parameters[upper(Utilities::trim(items[i].substr(0, equals)))] =
              equals == std::string::npos
                ? ""
                : Utilities::trim(items[i].substr(equals + 1));
          }
      }

      bool
      has(const std::string &key) const
      {
        return parameters.count(key) > 0;
      }
    };

    // The integers of a data line "1, 2, 3," (empty items skipped).
    std::vector<long>
    integers(const std::string &line, const std::string &file)
    {
      std::vector<long> values;
      for (const std::string &item : Utilities::split_string_list(line, ','))
        if (!item.empty())
          {
            std::size_t end = 0;
            long        v   = -1;
            try
              {
                v = std::stol(item, &end);
              }
            catch (const std::exception &)
              {
                end = 0;
              }
            AssertThrow(end == item.size(),
                        ExcMessage(file + ": <" + item + "> in the line <" +
                                   line + "> is not an integer."));
            values.push_back(v);
          }
      return values;
    }

    // What the reading keeps besides the rewritten text.
    struct Reading
    {
      explicit Reading(const std::string &file)
          : file(file)
      {
      }

      const std::string                        file;
      std::ostringstream                       out;
      long                                     n_elements = 0;
      std::vector<std::string>                 zones;
      std::map<std::string, std::vector<long>> members;
      // The elements of the current '*Element, elset=...' section.
      std::string element_set;
      // Every set's and surface's upper-case name: deal.II's reader
      // upper-cases names, so two of one kind may not differ in case only.
      std::map<std::string, std::string> spelled;

      void
      name(const std::string &n, const std::string &what)
      {
        AssertThrow(!n.empty(),
                    ExcMessage(file + ": a " + what + " without a name."));
        const auto [it, is_new] = spelled.emplace(what + upper(n), n);
        AssertThrow(is_new,
                    ExcMessage(file + ": the " + what + " <" + n + "> is " +
                               (it->second == n
                                  ? "defined twice."
                                  : "named like <" + it->second +
                                      "> but for case (Abaqus names are "
                                      "case-insensitive); rename one.")));
      }

      void
      new_set(const std::string &set, const bool internal)
      {
        name(set, "element set");
        if (!internal)
          zones.push_back(set);
      }

      // After an '*Element, elset=...' section: its set, for deal.II.
      void
      end_element_section()
      {
        if (element_set.empty())
          return;
        out << "*Elset, elset=" << element_set << "\n";
        const std::vector<long> &m = members[element_set];
        for (unsigned int i = 0; i < m.size(); ++i)
          out << m[i] << (i % 16 == 15 || i + 1 == m.size() ? ",\n" : ", ");
        element_set.clear();
      }

      void
      element(const std::string &line)
      {
        const std::vector<long> v = integers(line, file);
        if (v.empty())
          return;
        const std::string hint =
          v.size() == 4 || v.size() == 7
            ? "is a triangle; FuzzyContact needs quadrilaterals: mesh the part "
              "with quadrilateral elements (Abaqus/CAE: Mesh > Element Shape > "
              "Quad; Gmsh: 'Mesh.RecombineAll = 1;')"
            : "is not a first-order quadrilateral (4 nodes; it has " +
                std::to_string(v.size() - 1) +
                "); FuzzyContact reads CPS4/CPE4-type elements, the element "
                "degree is the component's 'fe degree'";
        AssertThrow(v.size() == 5,
                    ExcMessage(file + ": element " + std::to_string(v[0]) +
                               " " + hint + "."));
        AssertThrow(v[0] == ++n_elements,
                    ExcMessage(file + ": element " + std::to_string(v[0]) +
                               " should be numbered " +
                               std::to_string(n_elements) +
                               ": deal.II's reader needs the elements "
                               "numbered 1, 2, ... in the order of the "
                               "file; renumber them."));
        if (!element_set.empty())
          members[element_set].push_back(v[0]);
        out << line << "\n";
      }

      void
      set_members(const std::string &set,
                  const bool         generate,
                  const std::string &line)
      {
        const std::vector<long> v = integers(line, file);
        if (!generate)
          members[set].insert(members[set].end(), v.begin(), v.end());
        else if (v.size() >= 2)
          {
            const long step = v.size() > 2 ? v[2] : 1;
            AssertThrow(step >= 1,
                        ExcMessage(file + ": element set <" + set +
                                   ">: the step of 'generate' must be "
                                   "positive."));
            for (long e = v[0]; e <= v[1]; e += step)
              members[set].push_back(e);
          }
        out << line << "\n";
      }

      // One *Solid Section per zone, after checking that the zones do not
      // share elements and list only elements the file has.
      void
      add_zones(MeshFileInfo &info)
      {
        std::map<long, std::string> zone_of;
        for (unsigned int z = 0; z < zones.size(); ++z)
          {
            for (const long e : members[zones[z]])
              {
                AssertThrow(e >= 1 && e <= n_elements,
                            ExcMessage(file + ": element set <" + zones[z] +
                                       "> lists element " + std::to_string(e) +
                                       ", which the file does not have."));
                const auto [it, is_new] = zone_of.emplace(e, zones[z]);
                AssertThrow(is_new || it->second == zones[z],
                            ExcMessage(file + ": the element sets <" +
                                       it->second + "> and <" + zones[z] +
                                       "> share element " + std::to_string(e) +
                                       "; zones are disjoint element sets: "
                                       "mark helper sets 'internal' or remove "
                                       "them."));
              }
            info.material_ids[zones[z]] =
              static_cast<types::material_id>(z + 1);
            out << "*Solid Section, elset=" << zones[z] << ", material=zone-"
                << z + 1 << "\n";
          }
      }
    };
  } // namespace


  std::string
  abaqus_grid_in_text(const std::string &text,
                      MeshFileInfo      &info,
                      const std::string &where)
  {
    Reading            r(where + ": <" + info.file + ">");
    std::istringstream in(text);
    std::string        line, section, set;
    bool               generate = false;
    while (std::getline(in, line))
      {
        line = Utilities::trim(line);
        if (line.empty() || line.compare(0, 2, "**") == 0)
          continue;
        if (line[0] != '*')
          {
            if (section == "NODE")
              r.out << line << "\n";
            else if (section == "SURFACE") // "set or element, S3" for deal.II
              {
                for (const std::string &item :
                     Utilities::split_string_list(line, ','))
                  r.out << item << (item.empty() ? "" : ", ");
                r.out << "\n";
              }
            else if (section == "ELEMENT")
              r.element(line);
            else if (section == "ELSET")
              r.set_members(set, generate, line);
            continue;
          }
        const Keyword keyword(line);
        if (section == "ELEMENT")
          r.end_element_section();
        section = keyword.name;
        if (section == "STEP")
          break;
        if (section == "NODE")
          r.out << line << "\n";
        else if (section == "ELEMENT")
          {
            r.out << "*Element, type="
                  << (keyword.has("TYPE") ? keyword.parameters.at("TYPE") : "")
                  << "\n";
            if (keyword.has("ELSET"))
              {
                r.element_set = keyword.parameters.at("ELSET");
                r.new_set(r.element_set, false);
              }
          }
        else if (section == "ELSET")
          {
            set = keyword.has("ELSET") ? keyword.parameters.at("ELSET") : "";
            generate = keyword.has("GENERATE");
            r.new_set(set, keyword.has("INTERNAL"));
            r.out << "*Elset, elset=" << set << (generate ? ", generate" : "")
                  << "\n";
          }
        else if (section == "SURFACE")
          {
            const std::string name =
              keyword.has("NAME") ? keyword.parameters.at("NAME") : "";
            r.name(name, "surface");
            AssertThrow(!keyword.has("TYPE") ||
                          upper(keyword.parameters.at("TYPE")) == "ELEMENT",
                        ExcMessage(r.file + ": the surface <" + name +
                                   "> is not element-based; FuzzyContact "
                                   "reads surfaces of element faces "
                                   "('*Surface, type=ELEMENT')."));
            const auto id =
              static_cast<types::boundary_id>(info.boundary_ids.size() + 1);
            info.boundary_ids[name] = id;
            r.out << "*Surface, type=ELEMENT, name=" << id << "\n";
          }
      }
    if (section == "ELEMENT")
      r.end_element_section();
    AssertThrow(r.n_elements > 0,
                ExcMessage(r.file + " has no '*Element' lines."));
    AssertThrow(!info.boundary_ids.empty(),
                ExcMessage(r.file +
                           " defines no surface, so no face can be clamped, "
                           "loaded or put in contact; add '*Surface, "
                           "type=ELEMENT, name=...' for each face the scene "
                           "uses."));
    r.add_zones(info);
    return r.out.str();
  }


  void
  restore_node_coordinates(const std::string &grid_in_text,
                           Triangulation<2>  &triangulation)
  {
    // Each coordinate as deal.II's UCD text has it: scientific notation,
    // precision 8, read back.
    const auto rounded = [](const double x) {
      std::ostringstream s;
      s.setf(std::ios::scientific, std::ios::floatfield);
      s.precision(8);
      s << x;
      return std::strtod(s.str().c_str(), nullptr);
    };
    std::map<std::pair<double, double>, Point<2>> exact;
    std::map<std::pair<double, double>, bool>     ambiguous;
    std::istringstream                            in(grid_in_text);
    std::string                                   line;
    bool                                          nodes = false;
    while (std::getline(in, line))
      {
        if (!line.empty() && line[0] == '*')
          nodes = upper(line).compare(0, 5, "*NODE") == 0;
        else if (nodes)
          {
            const auto items = Utilities::split_string_list(line, ',');
            if (items.size() < 3)
              continue;
            const Point<2> p(std::strtod(items[1].c_str(), nullptr),
                             std::strtod(items[2].c_str(), nullptr));
            const std::pair<double, double> key(rounded(p[0]), rounded(p[1]));
            ambiguous[key] =
              ambiguous[key] || (exact.count(key) > 0 && exact[key] != p);
            exact[key] = p;
          }
      }
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const std::pair<double, double> key(cell->vertex(v)[0],
                                              cell->vertex(v)[1]);
          const auto                      it = exact.find(key);
          if (it != exact.end() && !ambiguous[key])
            cell->vertex(v) = it->second;
        }
  }
} // namespace FuzzyContact
