// The load history of a scene (Scene::load_stages): the `Stage <name>`
// subsections named by the scene key `load stages`.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>

namespace FuzzyContact
{
  bool
  LoadStage::ramps(const unsigned int c, const unsigned int l) const
  {
    return std::find(loads.begin(),
                     loads.end(),
                     std::array<unsigned int, 2>{{c, l}}) != loads.end();
  }


  void
  Scene::declare_load_stages(ParameterHandler &prm) const
  {
    for (const LoadStage &stage : load_stages)
      {
        prm.enter_subsection("Stage " + stage.name);
        prm.declare_entry("loads",
                          "",
                          Patterns::Anything(),
                          "The loads the stage ramps from 0 to full, as "
                          "<component>.<load or support>, comma-separated.",
                          /*has_to_be_set=*/true);
        prm.declare_entry("load steps",
                          "1",
                          Patterns::Integer(),
                          "Equal load steps of the stage (at least 1).");
        prm.leave_subsection();
      }
  }


  namespace
  {
    // Every load of the scene as <component>.<load>, comma-separated.
    std::string
    load_names(const std::vector<ComponentDescription> &components)
    {
      std::string names;
      for (const ComponentDescription &component : components)
        for (const EdgeLoad &load : component.loads)
          names +=
            (names.empty() ? "" : ", ") + component.name + "." + load.name;
      return names.empty() ? "(none)" : names;
    }
  } // namespace


  void
  Scene::parse_load_stages(ParameterHandler &prm)
  {
    // stage_of[c][l]: the stage that ramps load l of component c.
    std::vector<std::vector<int>> stage_of;
    for (const ComponentDescription &component : components)
      stage_of.emplace_back(component.loads.size(), -1);
    for (unsigned int s = 0; s < load_stages.size(); ++s)
      {
        LoadStage        &stage = load_stages[s];
        const std::string where = "Stage " + stage.name;
        prm.enter_subsection("Stage " + stage.name);
        const long steps = prm.get_integer("load steps");
        AssertThrow(steps >= 1,
                    ExcMessage(where + ": load steps must be at least 1, got " +
                               std::to_string(steps) + "."));
        // Each step is a contact solve of every model: step-3's cap.
        AssertThrow(steps <= 1000,
                    ExcMessage(where +
                               ": load steps must be at most 1000 (each step "
                               "is a contact solve), got " +
                               std::to_string(steps) + "."));
        stage.n_load_steps     = static_cast<unsigned int>(steps);
        const std::string text = prm.get("loads");
        prm.leave_subsection();

        stage.loads.clear();
        for (const std::string &name : Utilities::split_string_list(text, ','))
          {
            const std::size_t dot   = name.find('.');
            bool              found = false;
            for (unsigned int c = 0; c < components.size() && !found; ++c)
              for (unsigned int l = 0; l < components[c].loads.size(); ++l)
                if (dot != std::string::npos &&
                    name.substr(0, dot) == components[c].name &&
                    name.substr(dot + 1) == components[c].loads[l].name)
                  {
                    AssertThrow(stage_of[c][l] < 0,
                                ExcMessage(
                                  where + ": loads: <" + name +
                                  "> is already in stage " +
                                  load_stages[stage_of[c][l]].name +
                                  "; every load must be in exactly one "
                                  "stage."));
                    stage_of[c][l] = s;
                    stage.loads.push_back({{c, l}});
                    found = true;
                    break;
                  }
            AssertThrow(found,
                        ExcMessage(where + ": loads: <" + name +
                                   "> is not a load of the scene (a "
                                   "<component>.<load or support>); it has: " +
                                   load_names(components) + "."));
          }
        AssertThrow(!stage.loads.empty(),
                    ExcMessage(where +
                               ": loads: a stage needs at least one "
                               "load; the scene has: " +
                               load_names(components) + "."));
      }
    if (load_stages.empty())
      return;
    for (unsigned int c = 0; c < components.size(); ++c)
      for (unsigned int l = 0; l < components[c].loads.size(); ++l)
        AssertThrow(stage_of[c][l] >= 0,
                    ExcMessage("Scene: load stages: the load <" +
                               components[c].name + "." +
                               components[c].loads[l].name +
                               "> is in no stage; every load must be in "
                               "exactly one stage."));
  }
} // namespace FuzzyContact
