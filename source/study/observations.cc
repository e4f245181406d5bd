#include <fuzzycontact/base/input.h>
#include <fuzzycontact/study/observations.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <regex>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    const char *const accepted =
      "<component>.node(x, y).ux or .uy, slave.ux, slave.uy, master1.ux, "
      "master1.uy, master2.ux, master2.uy, Fn, Ft, <pair>.Fn, <pair>.Ft, "
      "<pair>.max_pressure, <pair>.max_shear or <pair>.contact_length";

    // <component>.node(x, y).<ux|uy>
    const std::regex node_pattern(
      R"(^([A-Za-z0-9_-]+)\.node\(\s*([^,()]+?)\s*,\s*([^,()]+?)\s*\)\.(ux|uy)$)");

    // The point to 1e-9 of @p size (a body's size: the mesh's precision),
    // in at most 10 significant digits.
    std::string
    point_string(const Point<2> &p, const double size)
    {
      const double unit =
        size > 0 ? std::pow(10., std::floor(std::log10(size)) - 9) : 0.;
      std::ostringstream s;
      s << std::setprecision(10) << "(";
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double x = unit > 0 ? std::round(p[d] / unit) * unit : p[d];
          s << (d > 0 ? ", " : "") << (x == 0 ? 0. : x);
        }
      s << ")";
      return s.str();
    }

    template <typename T, typename Name>
    std::string
    names_of(const std::vector<T> &items, const Name &name)
    {
      std::string list;
      for (const T &item : items)
        list += (list.empty() ? "" : ", ") + name(item);
      return list.empty() ? "none" : list;
    }

    // What a name says before any mesh exists: its kind, pair (or -1), and
    // for a node its component name and point.
    struct Parsed
    {
      Observation::Kind kind = Observation::Kind::displacement;
      int               pair = -1;
      std::string       alias; // slave, master1, master2, or empty
      std::string       component;
      Point<2>          point;
      unsigned int      direction = 0;
    };

    Parsed
    parse(const std::string &name, const Scene &scene, const std::string &what)
    {
      const std::string where = what + ": <" + name + ">";
      Parsed            p;
      std::smatch       match;
      if (std::regex_match(name, match, node_pattern))
        {
          p.component = match[1];
          bool found  = false;
          for (const ComponentDescription &c : scene.components)
            found = found || c.name == p.component;
          AssertThrow(found,
                      ExcMessage(where + ": the scene has no component <" +
                                 p.component + "> (its components: " +
                                 names_of(scene.components,
                                          [](const auto &c) {
                                            return c.name;
                                          }) +
                                 ")."));
          p.point     = Point<2>(Input::to_double(match[2], where + ": x"),
                             Input::to_double(match[3], where + ": y"));
          p.direction = match[4] == "ux" ? 0 : 1;
          return p;
        }
      if (name == "Fn" || name == "Ft")
        {
          p.kind = name == "Fn" ? Observation::Kind::normal_force
                                : Observation::Kind::tangential_force;
          return p;
        }
      const std::string::size_type dot = name.rfind('.');
      AssertThrow(dot != std::string::npos && dot > 0,
                  ExcMessage(where + ": not an output; use " + accepted + "."));
      const std::string head = name.substr(0, dot);
      const std::string tail = name.substr(dot + 1);
      for (unsigned int k = 0; k < scene.contact_pairs.size(); ++k)
        if (scene.contact_pairs[k].name == head &&
            (tail == "Fn" || tail == "Ft" || tail == "max_pressure" ||
             tail == "max_shear" || tail == "contact_length"))
          {
            p.pair = k;
            p.kind = tail == "Fn"   ? Observation::Kind::normal_force
                     : tail == "Ft" ? Observation::Kind::tangential_force
                     : tail == "max_pressure" ? Observation::Kind::max_pressure
                     : tail == "max_shear"    ? Observation::Kind::max_shear
                                           : Observation::Kind::contact_length;
            return p;
          }
      if ((head == "slave" || head == "master1" || head == "master2") &&
          (tail == "ux" || tail == "uy"))
        {
          AssertThrow(!scene.contact_pairs.empty(),
                      ExcMessage(where + ": the scene has no contact pair, "
                                         "so it has no slave node."));
          p.alias     = head;
          p.direction = tail == "ux" ? 0 : 1;
          return p;
        }
      if (tail == "Fn" || tail == "Ft" || tail == "max_pressure" ||
          tail == "max_shear" || tail == "contact_length")
        AssertThrow(false,
                    ExcMessage(where + ": the scene has no contact pair <" +
                               head + "> (its contact pairs: " +
                               names_of(scene.contact_pairs,
                                        [](const auto &c) {
                                          return c.name;
                                        }) +
                               ")."));
      AssertThrow(false,
                  ExcMessage(where + ": not an output; use " + accepted + "."));
      return p;
    }
  } // namespace


  std::string
  Observation::unit() const
  {
    switch (kind)
      {
        case Kind::displacement:
        case Kind::contact_length:
          return "m";
        case Kind::normal_force:
        case Kind::tangential_force:
          return "N";
        case Kind::max_pressure:
        case Kind::max_shear:
          return "Pa";
      }
    return "";
  }


  std::string
  Observation::description() const
  {
    const std::string u = direction == 0 ? "u_x" : "u_y";
    const std::string of_pair =
      pair < 0 ? "" : " of contact pair " + name.substr(0, name.rfind('.'));
    switch (kind)
      {
        case Kind::displacement:
          if (name.rfind("slave.", 0) == 0)
            return u + " of the slave node";
          if (name.rfind("master", 0) == 0)
            return u + " of master node " + name.substr(6, 1);
          return u + " of " + name.substr(0, name.find('.')) + "'s node " +
                 point_string(position, body_size);
        case Kind::normal_force:
          return (pair < 0 ? "total normal force F_n"
                           : "normal force F_n" + of_pair);
        case Kind::tangential_force:
          return (pair < 0 ? "total tangential force F_t"
                           : "tangential force F_t" + of_pair);
        case Kind::max_pressure:
          return "largest contact pressure" + of_pair;
        case Kind::max_shear:
          return "largest contact shear traction" + of_pair;
        case Kind::contact_length:
          return "contact length" + of_pair;
      }
    return name;
  }


  std::string
  Observations::default_outputs()
  {
    return "slave.ux, slave.uy, Fn, Ft";
  }


  std::vector<std::string>
  Observations::split(const std::string &list, const std::string &what)
  {
    std::vector<std::string> names;
    std::string              current;
    int                      depth  = 0;
    const auto               finish = [&]() {
      const std::string name = Utilities::trim(current);
      AssertThrow(!name.empty(),
                  ExcMessage(what + ": the list <" + list +
                             "> contains an empty name."));
      AssertThrow(std::find(names.begin(), names.end(), name) == names.end(),
                  ExcMessage(what + ": <" + name + "> appears twice."));
      names.push_back(name);
      current.clear();
    };
    for (const char c : list)
      {
        depth += (c == '(') - (c == ')');
        AssertThrow(depth >= 0 && depth <= 1,
                    ExcMessage(what + ": unbalanced parentheses in <" + list +
                               ">."));
        if (c == ',' && depth == 0)
          finish();
        else
          current += c;
      }
    AssertThrow(depth == 0,
                ExcMessage(what + ": unbalanced parentheses in <" + list +
                           ">."));
    finish();
    return names;
  }


  void
  Observations::check(const std::vector<std::string> &names,
                      const Scene                    &scene,
                      const std::string              &what)
  {
    AssertThrow(!names.empty(), ExcMessage(what + ": name at least one."));
    for (const std::string &name : names)
      {
        const Parsed p = parse(name, scene, what);
        if (p.component.empty())
          continue;
        const ComponentDescription &c =
          scene.components[scene.component_index(p.component)];
        const double size      = c.lower_left.distance(c.upper_right);
        const double tolerance = 1e-8 * size;
        AssertThrow(p.point[0] >= c.lower_left[0] - tolerance &&
                      p.point[0] <= c.upper_right[0] + tolerance &&
                      p.point[1] >= c.lower_left[1] - tolerance &&
                      p.point[1] <= c.upper_right[1] + tolerance,
                    ExcMessage(what + ": <" + name + ">: the point " +
                               point_string(p.point, size) +
                               " lies outside component " + c.name + " " +
                               point_string(c.lower_left, size) + " - " +
                               point_string(c.upper_right, size) + "."));
      }
  }


  Observations::Observations(const std::vector<std::string> &names,
                             const ContactScene             &bodies)
      : interface(bodies.interface())
      , slave_node_(0)
      , dofs_(bodies.n_components())
  {
    const Scene &scene = bodies.scene();
    check(names, scene);
    for (const ContactPairDescription &pair : scene.contact_pairs)
      thickness.push_back(
        scene.components[scene.component_index(pair.slave_component)]
          .thickness);
    for (unsigned int k = 0; k < interface.n_nodes(); ++k)
      {
        const ContactNode &node = interface.node(k);
        node_pair.push_back(node.pair);
        pressure_area.push_back(node.tributary_length * thickness[node.pair]);
      }

    // The report node: the slave node farthest along its master tangent,
    // and the master segment under it (at a vertex, the segment on the
    // slave face's side).
    if (interface.n_nodes() > 0)
      {
        for (unsigned int k = 1; k < interface.n_nodes(); ++k)
          if (interface.node(k).tangent * interface.node(k).slave.position >
              interface.node(slave_node_).tangent *
                interface.node(slave_node_).slave.position)
            slave_node_ = k;
        const ContactNode &node     = interface.node(slave_node_);
        const auto        &segments = interface.master_segments(node.pair);
        const double       s        = node.tangent * node.projection;
        const double       centre   = interface.slave_face_centre(node.pair);
        const double       tolerance =
          1e-10 * (segments.back().s_end - segments.front().s_begin);
        const MasterSegment *best = nullptr;
        for (const MasterSegment &segment : segments)
          if (s >= segment.s_begin - tolerance &&
              s <= segment.s_end + tolerance &&
              (best == nullptr ||
               std::abs(0.5 * (segment.s_begin + segment.s_end) - centre) <
                 std::abs(0.5 * (best->s_begin + best->s_end) - centre)))
            best = &segment;
        Assert(best != nullptr, ExcInternalError());
        master_nodes = {{best->nodes.front(), best->nodes.back()}};
      }

    for (const std::string &name : names)
      {
        const Parsed p = parse(name, scene, "outputs");
        Observation  o;
        o.name      = name;
        o.kind      = p.kind;
        o.pair      = p.pair;
        o.direction = p.direction;
        if (p.kind == Observation::Kind::displacement)
          {
            if (p.alias == "slave")
              observe(o, interface.node(slave_node_).slave, p.direction);
            else if (!p.alias.empty())
              observe(o,
                      master_nodes[p.alias == "master1" ? 0 : 1],
                      p.direction);
            else
              {
                // The component's node nearest to the point.
                const unsigned int c = scene.component_index(p.component);
                const Component   &component = bodies.component(c);
                double             best = std::numeric_limits<double>::max();
                for (unsigned int i = 0; i < component.n_dofs(); ++i)
                  if (component.dof_directions()[i] == p.direction &&
                      component.support_points()[i].distance(p.point) < best)
                    {
                      best  = component.support_points()[i].distance(p.point);
                      o.dof = i;
                    }
                o.component = c;
                o.position  = component.support_points()[o.dof];
                FaceNode node{c, o.position, {{0, 0}}};
                node.dofs[p.direction] = o.dof;
                observe(o, node, p.direction);
              }
          }
        else
          positions.push_back(0);
        if (p.kind == Observation::Kind::displacement)
          {
            const std::vector<Point<2>> &points =
              bodies.component(o.component).support_points();
            Point<2> low = points.front(), high = points.front();
            for (const Point<2> &x : points)
              for (unsigned int d = 0; d < 2; ++d)
                {
                  low[d]  = std::min(low[d], x[d]);
                  high[d] = std::max(high[d], x[d]);
                }
            o.body_size = low.distance(high);
          }
        observations.push_back(o);
      }
  }


  void
  Observations::observe(Observation &o, const FaceNode &node, const int d)
  {
    o.component = node.component;
    o.position  = node.position;
    o.dof       = node.dofs[d];
    auto &list  = dofs_[o.component];
    auto  it    = std::find(list.begin(), list.end(), o.dof);
    if (it == list.end())
      {
        list.push_back(o.dof);
        it = list.end() - 1;
      }
    positions.push_back(it - list.begin());
  }


  unsigned int
  Observations::size() const
  {
    return observations.size();
  }


  const Observation &
  Observations::operator[](const unsigned int i) const
  {
    AssertIndexRange(i, observations.size());
    return observations[i];
  }


  std::vector<std::string>
  Observations::names() const
  {
    std::vector<std::string> n;
    for (const Observation &o : observations)
      n.push_back(o.name);
    return n;
  }


  unsigned int
  Observations::index(const std::string &name) const
  {
    for (unsigned int i = 0; i < observations.size(); ++i)
      if (observations[i].name == name)
        return i;
    AssertThrow(false,
                ExcMessage("Observations: there is no output <" + name + ">."));
    return 0;
  }


  const ObservedDofs &
  Observations::dofs() const
  {
    return dofs_;
  }


  unsigned int
  Observations::slave_node() const
  {
    return slave_node_;
  }


  std::vector<double>
  Observations::values(const ContactSolution &s) const
  {
    AssertThrow(s.p.size() == interface.n_rows(),
                ExcMessage("Observations: the solution is not one of this "
                           "scene's contact interface."));
    std::vector<double> values;
    for (unsigned int i = 0; i < observations.size(); ++i)
      {
        const Observation &o = observations[i];
        double             v = 0;
        if (o.kind == Observation::Kind::displacement)
          {
            AssertThrow(o.component < s.observed.size() &&
                          positions[i] < s.observed[o.component].size(),
                        ExcMessage("Observations: the solver did not report "
                                   "the displacement that output " +
                                   o.name + " needs."));
            v = s.observed[o.component][positions[i]];
          }
        else
          {
            // Straight over the forces (an output is read at every
            // evaluation: on a small scene its loop over the slave nodes
            // cost a tenth of the reduced one).
            const int           pair = o.pair;
            const unsigned int  n    = interface.n_nodes();
            const double *const p    = s.p.begin();
            for (unsigned int k = 0; k < n; ++k)
              {
                if (pair >= 0 && node_pair[k] != pair)
                  continue;
                switch (o.kind)
                  {
                    case Observation::Kind::normal_force:
                      v += p[normal_row(k)];
                      break;
                    case Observation::Kind::tangential_force:
                      v += p[tangential_row(k)];
                      break;
                    case Observation::Kind::max_pressure:
                      v = std::max(v, p[normal_row(k)] / pressure_area[k]);
                      break;
                    case Observation::Kind::max_shear:
                      v = std::max(v,
                                   std::abs(p[tangential_row(k)]) /
                                     pressure_area[k]);
                      break;
                    case Observation::Kind::contact_length:
                      if (s.status[k] != ContactStatus::open)
                        v += interface.node(k).tributary_length;
                      break;
                    default:
                      break;
                  }
              }
          }
        values.push_back(v);
      }
    return values;
  }
} // namespace FuzzyContact
