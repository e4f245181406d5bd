// Helpers shared by the GoogleTest programs.

#ifndef fuzzycontact_tests_test_utilities_h
#define fuzzycontact_tests_test_utilities_h

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_state.h>

#include <deal.II/base/exceptions.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace FuzzyContact
{
  namespace Testing
  {
    /** The repository's top folder (set by CMake). */
    inline const std::string source_dir = FUZZYCONTACT_SOURCE_DIR;

    /**
     * @p text with the first occurrence of @p from replaced by @p to (a bad
     * input made from a good one); a test failure if @p from is absent.
     */
    inline std::string
    replace(std::string text, const std::string &from, const std::string &to)
    {
      const auto pos = text.find(from);
      EXPECT_NE(pos, std::string::npos)
        << "test setup: <" << from << "> not found";
      if (pos != std::string::npos)
        text.replace(pos, from.size(), to);
      return text;
    }

    /** The fuzzy parameters of a step file's text, bound to @p scene. */
    inline FuzzyParameterSet
    fuzzy_parameters(const Scene &scene, const std::string &text)
    {
      FuzzyParameterSet set;
      Input::parse_in_passes(
        text,
        "test.prm",
        [&](dealii::ParameterHandler &prm) {
          set.declare_parameters(prm);
        },
        [&](dealii::ParameterHandler &prm) {
          return set.learn_names(prm);
        },
        [&](dealii::ParameterHandler &prm) {
          set.parse_parameters(prm, scene);
        });
      return set;
    }

    /** The user-facing message of the exception @p f throws ("" if none). */
    template <typename F>
    std::string
    error_of(const F &f)
    {
      try
        {
          f();
        }
      catch (const dealii::ExceptionBase &e)
        {
          return Input::message_of(e);
        }
      return "";
    }

    /** The oedometric modulus: sigma_yy / eps_yy when eps_xx = eps_zz = 0. */
    inline double
    oedometric(const double E, const double nu)
    {
      return E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    }

    /**
     * The uniaxial state of prm/column.prm at @p state (rollers on every
     * vertical side, plane strain: eps_xx = 0; the column's zones
     * horizontal layers of one modulus): sigma_yy(y) = -(the weight above
     * y per unit area), u_y = int sigma_yy / E' dy from the clamped base.
     * Returns the contact force, u_y of the footing's top and u_y of the
     * column's top.
     */
    inline std::array<double, 3>
    column_closed_form(const Scene &s, const SceneState &state)
    {
      const double                g       = -s.gravity[1];
      const ComponentDescription &column  = s.components[0],
                                 &footing = s.components[1];
      const double W = column.length(), t = column.thickness;
      // The column's layers from the top down: each adds the integral of its
      // stress, -(q h + rho g h^2 / 2), q the pressure of those above.
      std::vector<std::array<double, 3>> layers; // top, height, density
      for (unsigned int z = 0; z < column.zones.size(); ++z)
        {
          const double lo =
            std::max(column.zones[z].y_range[0], column.lower_left[1]);
          const double hi =
            std::min(column.zones[z].y_range[1], column.upper_right[1]);
          layers.push_back({{hi, hi - lo, state.zone_densities[0][z]}});
        }
      std::sort(layers.begin(), layers.end(), [](const auto &a, const auto &b) {
        return a[0] > b[0];
      });
      double q = 0, column_integral = 0;
      for (const auto &layer : layers)
        {
          column_integral -=
            q * layer[1] + layer[2] * g * layer[1] * layer[1] / 2;
          q += layer[2] * g * layer[1];
        }
      const double Hb = footing.height(), rho_b = state.zone_densities[1][0];
      const double Eb =
        oedometric(state.zone_moduli[1][0], footing.zones[0].poissons_ratio);
      const double Ec =
        oedometric(state.zone_moduli[0][0], column.zones[0].poissons_ratio);
      const double footing_top = -(q * Hb + rho_b * g * Hb * Hb / 2) / Eb;
      return {{q * W * t, footing_top, footing_top + column_integral / Ec}};
    }
  } // namespace Testing
} // namespace FuzzyContact

#endif
