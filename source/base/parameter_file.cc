#include <fuzzycontact/base/parameter_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cctype>
#include <map>
#include <set>
#include <sstream>

namespace FuzzyContact
{
  namespace Input
  {
    namespace
    {
      // Trimmed, tabs as blanks, runs of blanks as one.
      std::string
      normalised(const std::string &text)
      {
        std::string out;
        for (const char c : Utilities::trim(text))
          {
            const char d = (c == '\t') ? ' ' : c;
            if (d == ' ' && !out.empty() && out.back() == ' ')
              continue;
            out += d;
          }
        return out;
      }

      // True if @p line starts with the keyword (either case) and a blank.
      bool
      starts_with_keyword(const std::string &line,
                          const std::string &lower_case)
      {
        if (line.size() <= lower_case.size())
          return false;
        std::string head = line.substr(0, lower_case.size());
        for (char &c : head)
          c = std::tolower(static_cast<unsigned char>(c));
        return head == lower_case && (line[lower_case.size()] == ' ');
      }

      bool
      is_end(const std::string &line)
      {
        return line == "end" || line == "END";
      }

      int
      hex_value(const char c)
      {
        if (c >= '0' && c <= '9')
          return c - '0';
        if (c >= 'a' && c <= 'f')
          return c - 'a' + 10;
        if (c >= 'A' && c <= 'F')
          return c - 'A' + 10;
        return -1;
      }

      // One mangled name ("lower_20left_20corner") in the user's spelling.
      std::string
      demangle_name(const std::string &mangled)
      {
        std::string name;
        for (std::size_t i = 0; i < mangled.size(); ++i)
          if (mangled[i] == '_' && i + 2 < mangled.size() &&
              hex_value(mangled[i + 1]) >= 0 && hex_value(mangled[i + 2]) >= 0)
            {
              name += static_cast<char>(16 * hex_value(mangled[i + 1]) +
                                        hex_value(mangled[i + 2]));
              i += 2;
            }
          else
            name += mangled[i];
        return name;
      }

      // True if every '_' of @p token starts an escape and one of them is a
      // blank or a dot: a name ParameterHandler mangled.
      bool
      looks_mangled(const std::string &token)
      {
        bool space_or_dot = false;
        for (std::size_t i = 0; i < token.size(); ++i)
          if (token[i] == '_')
            {
              if (i + 2 >= token.size() || hex_value(token[i + 1]) < 0 ||
                  hex_value(token[i + 2]) < 0)
                return false;
              const std::string code = token.substr(i + 1, 2);
              space_or_dot = space_or_dot || code == "20" || code == "2e";
            }
        return space_or_dot;
      }
    } // namespace


    ParameterFileStructure
    scan_parameter_text(const std::string &text, const std::string &filename)
    {
      ParameterFileStructure             structure;
      std::vector<std::string>           path;
      std::map<std::string, std::size_t> first_line_of;
      std::istringstream                 in(text);
      std::string                        raw, line;
      std::size_t                        line_number = 0, start_line = 0;
      while (std::getline(in, raw))
        {
          ++line_number;
          if (line.empty())
            start_line = line_number;
          // Comments end the line; a backslash at its end continues it.
          const std::size_t hash = raw.find('#');
          if (hash != std::string::npos)
            raw.erase(hash);
          std::string trimmed = Utilities::trim(raw);
          if (!trimmed.empty() && trimmed.back() == '\\')
            {
              trimmed.pop_back();
              line += trimmed + " ";
              continue;
            }
          line += trimmed;
          const std::string l = normalised(line);
          line.clear();
          if (l.empty())
            continue;

          if (starts_with_keyword(l, "subsection"))
            {
              const std::string name = normalised(l.substr(10));
              if (path.empty())
                structure.top_level_subsections.push_back(name);
              path.push_back(name);
            }
          else if (is_end(l))
            {
              if (!path.empty())
                path.pop_back();
            }
          else if (starts_with_keyword(l, "set"))
            {
              const std::size_t equal = l.find('=');
              if (equal == std::string::npos)
                continue;
              const std::string key = normalised(l.substr(4, equal - 4));
              std::string       where;
              for (const std::string &p : path)
                where += (where.empty() ? "" : ", ") + p;
              const std::string id = where + "\x1f" + key;
              const auto        first = first_line_of.find(id);
              AssertThrow(first == first_line_of.end(),
                          ExcMessage(
                            filename + ", line " + std::to_string(start_line) +
                            ": the key <" + key + "> is set a second time" +
                            (where.empty() ? std::string() :
                                             " in subsection <" + where + ">") +
                            " (first on line " +
                            std::to_string(first->second) +
                            "). deal.II would silently use the last value; "
                            "set each key once."));
              first_line_of[id] = start_line;
            }
        }
      return structure;
    }


    std::vector<std::string>
    demangle_path(const std::string &mangled)
    {
      std::vector<std::string> names;
      for (const std::string &part : Utilities::split_string_list(mangled, '.'))
        names.push_back(demangle_name(part));
      return names;
    }


    void
    check_mandatory_entries(const ParameterHandler &prm,
                            const std::string      &filename)
    {
      const std::set<std::string> missing = prm.get_entries_wrongly_not_set();
      if (missing.empty())
        return;
      std::string list;
      for (const std::string &mangled : missing)
        {
          const std::vector<std::string> path = demangle_path(mangled);
          std::string                     where;
          for (std::size_t i = 0; i + 1 < path.size(); ++i)
            where += (where.empty() ? "" : ", ") + path[i];
          list += std::string(list.empty() ? "" : "; ") + "<" + path.back() +
                  ">" +
                  (where.empty() ? std::string(" (at the top level)") :
                                   " in subsection <" + where + ">");
        }
      AssertThrow(false,
                  ExcMessage(filename + ": " +
                             (missing.size() == 1 ? "a mandatory key is" :
                                                    "mandatory keys are") +
                             " not set: " + list +
                             ". Add 'set <key> = <value>' inside the "
                             "subsection."));
    }


    std::string
    demangle_message(const std::string &message)
    {
      std::string out, token;
      const auto  flush = [&]() {
        out += looks_mangled(token) ? demangle_name(token) : token;
        token.clear();
      };
      for (const char c : message)
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '_')
          token += c;
        else
          {
            flush();
            out += c;
          }
      flush();
      return out;
    }
  } // namespace Input
} // namespace FuzzyContact
