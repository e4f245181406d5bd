// What a scene may ask for: physically meaningful ranges of its numbers,
// the size of the models it leads to, and warnings for input that is valid
// but probably not meant.
//
// The ranges are wide (any structural material, any beam from a micrometre
// to a kilometre) but finite: a modulus of 1e308 Pa or a load of 1e308 N
// overflows the matrices long before it means anything, and a friction
// coefficient of 1e10 stops every contact solver from converging.

#ifndef fuzzycontact_scene_scene_limits_h
#define fuzzycontact_scene_scene_limits_h

#include <fuzzycontact/scene/scene.h>

#include <optional>
#include <string>
#include <vector>

namespace FuzzyContact
{
  namespace SceneLimits
  {
    /** The accepted ranges (SI units). */
    constexpr double min_youngs_modulus = 1e3, max_youngs_modulus = 1e13;
    constexpr double min_density = 1e-1, max_density = 1e5;
    constexpr double min_poissons_ratio = -0.99, max_poissons_ratio = 0.49;
    constexpr double min_length = 1e-6, max_length = 1e3;
    constexpr double max_coordinate = 1e4;
    constexpr double max_force      = 1e12;
    constexpr double max_friction   = 10;
    /** |g| [m/s^2]: about 1000 times the Earth's (a centrifuge test). */
    constexpr double max_gravity      = 1e4;
    constexpr long   max_subdivisions = 100000;
    constexpr double max_cells        = 4e6;

    /** The memory a run may plan for [bytes]: most of the 24 GiB machine. */
    constexpr double memory_budget = 20.0 * 1024 * 1024 * 1024;

    /** Each of these throws, naming @p what, unless the value is in range. */
    double
    youngs_modulus(const double value, const std::string &what);
    double
    density(const double value, const std::string &what);
    double
    force(const double value, const std::string &what);

    /**
     * force() of @p text, or none if @p text is @p keyword ("scene", say);
     * a message names @p what and both choices.
     */
    std::optional<double>
    optional_force(const std::string &text,
                   const std::string &keyword,
                   const std::string &what);
    double
    friction_coefficient(const double value, const std::string &what);
    /** Throws unless @p g is finite and |g| <= max_gravity. */
    Tensor<1, 2>
    gravity(const Tensor<1, 2> &g, const std::string &what);

    /**
     * Checks every number of @p scene against the ranges above (called by
     * Scene::check()).
     */
    void
    check_ranges(const Scene &scene);

    /**
     * The DoFs of component @p c of @p scene after @p refinements global
     * refinements (both displacement components, clamped ones included).
     */
    double
    n_dofs(const Scene       &scene,
           const unsigned int c,
           const unsigned int refinements);

    /**
     * A rough upper estimate of the memory [bytes] of a run on @p scene with
     * @p refinements: sparse matrices and factorisations of every
     * component, and with @p static_correction the dense static correction
     * modes (a DoF-long vector per DoF of a contact face and per load).
     */
    double
    estimated_memory(const Scene       &scene,
                     const unsigned int refinements,
                     const bool         static_correction);

    /**
     * Throws, naming @p key (the key that sets the refinements) and the
     * estimate, if estimated_memory() exceeds memory_budget.
     */
    void
    check_memory(const Scene       &scene,
                 const unsigned int refinements,
                 const bool         static_correction,
                 const std::string &key = "mesh refinements");

    /**
     * Warnings for valid but suspicious input: a load on a clamped face
     * (it does nothing), a scene with no load.
     */
    std::vector<std::string>
    warnings(const Scene &scene);
  } // namespace SceneLimits
} // namespace FuzzyContact

#endif
