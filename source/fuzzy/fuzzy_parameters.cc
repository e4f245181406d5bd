#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <sstream>

namespace FuzzyContact
{
  std::string
  point_text(const std::vector<FuzzyParameter> &parameters,
             const std::vector<double>         &values)
  {
    std::ostringstream point;
    for (unsigned int i = 0; i < values.size() && i < parameters.size(); ++i)
      point << (i > 0 ? ", " : "") << parameters[i].quantity.name << " = "
            << values[i];
    return point.str();
  }


  using namespace dealii;

  void
  FuzzyParameterSet::declare_parameters(ParameterHandler &prm) const
  {
    prm.declare_entry("fuzzy parameters",
                      "",
                      Patterns::Anything(),
                      "Comma-separated scene quantities that are fuzzy "
                      "(P1.E, P1.root.rho, P1.tip.force, interface.mu, "
                      "interface.gap, ...); each has a subsection 'Fuzzy "
                      "parameter <name>'. Optional: a subsection alone "
                      "declares a fuzzy parameter.");
    for (const std::string &name : names_)
      {
        prm.enter_subsection("Fuzzy parameter " + name);
        prm.declare_entry("shape",
                          "triangular",
                          Patterns::Selection("crisp|triangular|trapezoidal"),
                          "Membership function.");
        prm.declare_entry("values",
                          "",
                          Patterns::Anything(),
                          "crisp: x; triangular: a, m, b; trapezoidal: a, "
                          "m1, m2, b (support [a, b], core [m1, m2]).",
                          /*has_to_be_set=*/true);
        prm.declare_entry("relative",
                          "false",
                          Patterns::Bool(),
                          "If true, the values are factors of the scene's "
                          "own value of the quantity.");
        prm.leave_subsection();
      }
  }


  void
  FuzzyParameterSet::add_names_of_subsections(
    const std::vector<std::string> &subsections)
  {
    const std::string prefix = "Fuzzy parameter ";
    for (const std::string &s : subsections)
      if (s.rfind(prefix, 0) == 0)
        {
          const std::string name = Utilities::trim(s.substr(prefix.size()));
          if (std::find(names_of_subsections_.begin(),
                        names_of_subsections_.end(),
                        name) == names_of_subsections_.end())
            names_of_subsections_.push_back(name);
        }
  }


  bool
  FuzzyParameterSet::learn_names(ParameterHandler &prm)
  {
    std::vector<std::string> names;
    for (const std::string &n :
         Utilities::split_string_list(prm.get("fuzzy parameters"), ','))
      {
        AssertThrow(!n.empty(),
                    ExcMessage("fuzzy parameters: the list contains an empty "
                               "name."));
        for (const std::string &other : names)
          AssertThrow(other != n,
                      ExcMessage("fuzzy parameters: <" + n +
                                 "> appears twice."));
        names.push_back(n);
      }
    for (const std::string &n : names_of_subsections_)
      if (std::find(names.begin(), names.end(), n) == names.end())
        names.push_back(n);
    const bool changed = names != names_;
    names_             = names;
    return changed;
  }


  void
  FuzzyParameterSet::parse_parameters(ParameterHandler &prm, const Scene &scene)
  {
    learn_names(prm);
    parameters_.clear();
    for (const std::string &name : names_)
      {
        const std::string where = "Fuzzy parameter " + name;
        FuzzyParameter    p;
        p.quantity = SceneQuantity::parse(name, scene);
        prm.enter_subsection(where);
        std::vector<double> values =
          Input::to_doubles(prm.get("values"), where + ": values");
        const bool relative = prm.get_bool("relative");
        if (relative)
          {
            const double nominal = p.quantity.value(scene);
            for (double &v : values)
              v *= nominal;
          }
        p.number = FuzzyNumber::from(prm.get("shape"), values, where);
        prm.leave_subsection();

        // Every value of the support must be admissible for the quantity,
        // and no two parameters may set the same value of the scene.
        SceneState check(scene);
        try
          {
            for (const double v : {p.number.points()[0], p.number.points()[3]})
              p.quantity.apply(check, scene, v);
          }
        catch (const ExceptionBase &e)
          {
            AssertThrow(false,
                        ExcMessage(
                          where + ": the ends of its support (" +
                          (relative ? "the values times the scene's "
                                      "value"
                                    : "the values") +
                          ") are not admissible: " + Input::message_of(e)));
          }
        for (const FuzzyParameter &other : parameters_)
          AssertThrow(!p.quantity.overlaps(other.quantity, scene),
                      ExcMessage("fuzzy parameters: <" + other.quantity.name +
                                 "> and <" + name +
                                 "> set the same value of the scene; declare "
                                 "only one of them."));
        parameters_.push_back(p);
      }
  }


  const std::vector<FuzzyParameter> &
  FuzzyParameterSet::parameters() const
  {
    return parameters_;
  }

  std::vector<FuzzyNumber>
  FuzzyParameterSet::numbers() const
  {
    std::vector<FuzzyNumber> n;
    for (const FuzzyParameter &p : parameters_)
      n.push_back(p.number);
    return n;
  }

  std::vector<std::string>
  FuzzyParameterSet::names() const
  {
    return names_;
  }

  SceneState
  FuzzyParameterSet::state(const Scene               &scene,
                           const std::vector<double> &values) const
  {
    AssertThrow(values.size() == parameters_.size(),
                ExcMessage("Expected one value per fuzzy parameter."));
    SceneState result(scene);
    for (unsigned int i = 0; i < values.size(); ++i)
      parameters_[i].quantity.apply(result, scene, values[i]);
    return result;
  }
} // namespace FuzzyContact
