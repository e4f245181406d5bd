#include <fuzzycontact/base/input.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace FuzzyContact
{
  namespace Input
  {
    double
    to_double(const std::string &text, const std::string &what)
    {
      const std::string trimmed = Utilities::trim(text);
      AssertThrow(!trimmed.empty(),
                  ExcMessage(what + ": a number is required, got nothing."));
      errno              = 0;
      char        *end   = nullptr;
      const double value = std::strtod(trimmed.c_str(), &end);
      AssertThrow(end != nullptr && *end == '\0' && errno == 0,
                  ExcMessage(what + ": <" + trimmed +
                             "> is not a number (or is out of range)."));
      AssertThrow(std::isfinite(value),
                  ExcMessage(what + ": <" + trimmed +
                             "> is not a finite number."));
      return value;
    }


    std::vector<double>
    to_doubles(const std::string &text,
               const std::string &what,
               const unsigned int expected_size)
    {
      const std::vector<std::string> items =
        Utilities::split_string_list(text, ',');
      if (expected_size != 0)
        AssertThrow(items.size() == expected_size,
                    ExcMessage(
                      what + ": expected " + std::to_string(expected_size) +
                      " comma-separated numbers, got <" + text + ">."));
      std::vector<double> values;
      for (const std::string &item : items)
        values.push_back(to_double(item, what));
      return values;
    }


    std::vector<std::string>
    to_names(const std::string &text, const std::string &what)
    {
      std::vector<std::string> names;
      if (Utilities::trim(text).empty())
        return names;
      std::set<std::string> seen;
      for (const std::string &name : Utilities::split_string_list(text, ','))
        {
          AssertThrow(!name.empty(),
                      ExcMessage(what + ": the list <" + text +
                                 "> contains an empty name."));
          for (const char c : name)
            AssertThrow(std::isalnum(static_cast<unsigned char>(c)) ||
                          c == '_' || c == '-',
                        ExcMessage(what + ": the name <" + name +
                                   "> may only contain letters, digits, "
                                   "'_' and '-'."));
          AssertThrow(seen.insert(name).second,
                      ExcMessage(what + ": the name <" + name +
                                 "> appears twice."));
          names.push_back(name);
        }
      return names;
    }


    double
    positive(const double value, const std::string &what)
    {
      AssertThrow(std::isfinite(value),
                  ExcMessage(what + " must be a finite number."));
      std::ostringstream message;
      message << what << " must be positive, got " << value << ".";
      AssertThrow(value > 0, ExcMessage(message.str()));
      return value;
    }


    double
    non_negative(const double value, const std::string &what)
    {
      AssertThrow(std::isfinite(value),
                  ExcMessage(what + " must be a finite number."));
      std::ostringstream message;
      message << what << " must not be negative, got " << value << ".";
      AssertThrow(value >= 0, ExcMessage(message.str()));
      return value;
    }


    double
    finite(const double value, const std::string &what)
    {
      AssertThrow(std::isfinite(value),
                  ExcMessage(what + " must be a finite number."));
      return value;
    }


    std::string
    resolve_relative_to(const std::string &path,
                        const std::string &reference_file)
    {
      const std::filesystem::path p(path);
      if (p.is_absolute())
        return path;
      return (std::filesystem::path(reference_file).parent_path() / p)
        .lexically_normal()
        .string();
    }


    std::string
    read_text_file(const std::string &filename)
    {
      std::ifstream in(filename);
      AssertThrow(in.good(),
                  ExcMessage("Cannot open the parameter file <" + filename +
                             ">."));
      std::ostringstream content;
      content << in.rdbuf();
      return content.str();
    }


    void
    parse_strictly(ParameterHandler &prm, const std::string &filename)
    {
      std::istringstream in(read_text_file(filename));
      prm.parse_input(in, filename, "", /*skip_undefined=*/false);
      prm.assert_that_entries_have_been_set();
    }


    void
    parse_in_passes(const std::string                             &text,
                    const std::string                             &source_name,
                    const std::function<void(ParameterHandler &)> &declare,
                    const std::function<bool(ParameterHandler &)> &learn_names,
                    const std::function<void(ParameterHandler &)> &parse)
    {
      // Each pass can only learn the names one level deeper, so a handful
      // of passes settles any sensible file.
      for (unsigned int pass = 0; pass < 8; ++pass)
        {
          ParameterHandler   prm;
          std::istringstream in(text);
          declare(prm);
          prm.parse_input(in, source_name, "", /*skip_undefined=*/true);
          if (!learn_names(prm))
            break;
        }
      ParameterHandler   prm;
      std::istringstream in(text);
      declare(prm);
      prm.parse_input(in, source_name, "", /*skip_undefined=*/false);
      prm.assert_that_entries_have_been_set();
      parse(prm);
    }


    std::string
    message_of(const ExceptionBase &exception)
    {
      std::ostringstream info;
      exception.print_info(info);
      // ParameterHandler spreads its messages over indented lines.
      std::istringstream lines(info.str());
      std::string        line, compact;
      while (std::getline(lines, line))
        {
          line = Utilities::trim(line);
          if (!line.empty())
            compact += (compact.empty() ? "" : " ") + line;
        }
      return compact;
    }
  } // namespace Input
} // namespace FuzzyContact
