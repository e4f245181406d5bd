#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/parameter_file.h>

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
      if (!(value > 0))
        {
          std::ostringstream message;
          message << what << " must be positive, got " << value << ".";
          AssertThrow(false, ExcMessage(message.str()));
        }
      return value;
    }


    double
    non_negative(const double value, const std::string &what)
    {
      AssertThrow(std::isfinite(value),
                  ExcMessage(what + " must be a finite number."));
      if (!(value >= 0))
        {
          std::ostringstream message;
          message << what << " must not be negative, got " << value << ".";
          AssertThrow(false, ExcMessage(message.str()));
        }
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
      namespace fs = std::filesystem;
      AssertThrow(!Utilities::trim(filename).empty(),
                  ExcMessage("A parameter file is needed, but its name is "
                             "empty."));
      std::error_code error;
      const auto      status = fs::status(filename, error);
      AssertThrow(fs::exists(status),
                  ExcMessage("Cannot open the parameter file <" + filename +
                             ">: there is no such file."));
      AssertThrow(!fs::is_directory(status),
                  ExcMessage("Cannot open the parameter file <" + filename +
                             ">: it is a folder, not a file."));
      AssertThrow(fs::is_regular_file(status),
                  ExcMessage("Cannot open the parameter file <" + filename +
                             ">: it is not a regular file."));
      std::ifstream in(filename);
      AssertThrow(in.good(),
                  ExcMessage("Cannot open the parameter file <" + filename +
                             ">: it cannot be read (permissions?)."));
      std::ostringstream content;
      content << in.rdbuf();
      AssertThrow(!in.bad(),
                  ExcMessage("Reading the parameter file <" + filename +
                             "> failed."));
      return content.str();
    }


    void
    parse_text(ParameterHandler  &prm,
               const std::string &text,
               const std::string &filename,
               const bool         skip_undefined)
    {
      std::istringstream in(text);
      try
        {
          prm.parse_input(in, filename, "", skip_undefined);
        }
      catch (const ExceptionBase &e)
        {
          // ParameterHandler's own messages may name subsections in their
          // internal, mangled form.
          AssertThrow(false, ExcMessage(demangle_message(message_of(e))));
        }
    }


    void
    parse_strictly(ParameterHandler &prm, const std::string &filename)
    {
      const std::string text = read_text_file(filename);
      scan_parameter_text(text, filename);
      parse_text(prm, text, filename, /*skip_undefined=*/false);
      check_mandatory_entries(prm, filename);
    }


    void
    parse_in_passes(const std::string                             &text,
                    const std::string                             &source_name,
                    const std::function<void(ParameterHandler &)> &declare,
                    const std::function<bool(ParameterHandler &)> &learn_names,
                    const std::function<void(ParameterHandler &)> &parse)
    {
      scan_parameter_text(text, source_name);
      // Each pass can only learn the names one level deeper, so a handful
      // of passes settles any sensible file.
      for (unsigned int pass = 0; pass < 8; ++pass)
        {
          ParameterHandler prm;
          declare(prm);
          parse_text(prm, text, source_name, /*skip_undefined=*/true);
          if (!learn_names(prm))
            break;
        }
      ParameterHandler prm;
      declare(prm);
      parse_text(prm, text, source_name, /*skip_undefined=*/false);
      check_mandatory_entries(prm, source_name);
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
      return demangle_message(compact);
    }
  } // namespace Input
} // namespace FuzzyContact
