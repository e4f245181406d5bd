// The parameters of a modal reanalysis: Young's moduli and densities of the
// material zones of one component, and the exact derivative matrices of K
// and M with respect to them.
//
// A parameter is a scene quantity (scene_quantity.h, the one parser of such
// names) that is a Young's modulus or a density: "<component>.<zone>.<E|rho>"
// (one zone, e.g. "P1.root.E") or "<component>.<E|rho>" (every zone of the
// component scaled together, e.g. "P1.rho", whose value is the area-weighted
// mean over the zones). Its value is handled as a relative change
//
//     t_k = P_k / P_k^0 - 1,
//
// so that the zones it acts on get E_z = E_z^0 (1 + sum_k t_k) (or rho_z
// likewise), summed over the parameters acting on zone z. Since K =
// sum_z E_z K_z and M = sum_z rho_z M_z, the matrices are affine in t:
//
//     K(t) = K0 + sum_k t_k K_k,   K_k = sum_{z in k} E_z^0 K_z,
//     M(t) = M0 + sum_k t_k M_k,   M_k = sum_{z in k} rho_z^0 M_z,
//
// exactly: K_k = P_k^0 dK/dP_k and M_k = P_k^0 dM/dP_k are the derivative
// matrices with respect to the relative changes. A modulus parameter has
// M_k = 0 and a density parameter K_k = 0. Working with relative changes
// keeps every Taylor coefficient dimensionless (a nominal mode has M-norm 1)
// whether the parameter is a modulus of 2e11 Pa or a density of 7900 kg/m^3.

#ifndef fuzzycontact_reanalysis_reanalysis_parameters_h
#define fuzzycontact_reanalysis_reanalysis_parameters_h

#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_quantity.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /** The material property a reanalysis parameter changes. */
  enum class MaterialProperty
  {
    youngs_modulus,
    density
  };

  /**
   * The scene of @p component alone (its plane model is irrelevant): the
   * scene on which the parameters of a reanalysis of that component are
   * named, so that they can be read without the rest of the scene.
   */
  Scene
  component_scene(const ComponentDescription &component);

  /**
   * One reanalysis parameter of a component, as named in a parameter file.
   */
  struct ReanalysisParameter
  {
    /** The full name, e.g. "P1.root.E" or "P1.rho". */
    std::string name;
    /** The component it belongs to. */
    std::string component;
    /** The zone it changes; empty for all zones of the component. */
    std::string      zone;
    MaterialProperty property;
    /** Indices of the zones it acts on (all of them if zone is empty). */
    std::vector<unsigned int> zones;
    /** The scene quantity it is, on component_scene() of its component. */
    SceneQuantity quantity;

    /**
     * Reads a parameter name (through SceneQuantity::parse) in @p scene and
     * checks that it is the Young's modulus or the density of the component
     * called @p component or of one of its zones. Throws a message naming
     * the parameter and what the component offers otherwise.
     */
    static ReanalysisParameter
    parse(const std::string &name,
          const Scene       &scene,
          const std::string &component);

    /** Same, on component_scene(@p component). */
    static ReanalysisParameter
    parse(const std::string &name, const ComponentDescription &component);
  };

  /**
   * Throws if two of @p parameters, parameters of @p component, change the
   * same property of the same zones (their derivative matrices would be
   * identical), naming them. Parameters that share only some zones (P1.E
   * and P1.root.E) may be declared together: their changes add up in the
   * shared zones, and their derivative matrices differ.
   */
  void
  check_distinct(const std::vector<ReanalysisParameter> &parameters,
                 const ComponentDescription             &component);

  /**
   * The zone moduli and densities of @p component after the relative changes
   * @p t of @p parameters, starting from @p nominal_moduli and
   * @p nominal_densities (one per zone). Throws a message naming the
   * parameters involved if a modulus or density would not be positive, or a
   * change is not finite. Works on descriptions only, so that input can be
   * checked before any mesh is built.
   */
  std::pair<std::vector<double>, std::vector<double>>
  perturbed_zone_materials(const ComponentDescription             &component,
                           const std::vector<ReanalysisParameter> &parameters,
                           const std::vector<double> &nominal_moduli,
                           const std::vector<double> &nominal_densities,
                           const std::vector<double> &t);

  /**
   * The affine parameter model of one component: the declared parameters,
   * their nominal values, and the derivative matrices K_k, M_k with respect
   * to their relative changes. The nominal state is the component's zone
   * materials when the model is built. The component must outlive the
   * model (its zone matrices are used, not copied).
   */
  class ParameterModel
  {
  public:
    /**
     * Builds the model for the named parameters of @p component. Throws
     * if a name does not parse (see ReanalysisParameter::parse) or if two
     * parameters change the same property of the same zones (their
     * derivative matrices would be identical).
     */
    ParameterModel(const Component                &component,
                   const std::vector<std::string> &parameter_names);

    const Component &
    component() const;

    unsigned int
    n_parameters() const;
    const ReanalysisParameter &
    parameter(const unsigned int k) const;
    const std::vector<ReanalysisParameter> &
    parameters() const;

    /**
     * Nominal value P_k^0 [Pa or kg/m^3]: the value of the parameter's scene
     * quantity with the component's zone materials at construction (the
     * zone's value, or for a component-wide parameter the area-weighted
     * mean of its zones' values).
     */
    double
    nominal_value(const unsigned int k) const;

    /** Relative changes t_k = P_k / P_k^0 - 1 from absolute values P_k. */
    std::vector<double>
    relative_changes(const std::vector<double> &values) const;

    /** True if K_k is not zero (a modulus parameter). */
    bool
    affects_stiffness(const unsigned int k) const;
    /** True if M_k is not zero (a density parameter). */
    bool
    affects_mass(const unsigned int k) const;

    /** K_k = P_k^0 dK/dP_k; empty matrix if !affects_stiffness(k). */
    const SparseMatrix<double> &
    stiffness_derivative(const unsigned int k) const;
    /** M_k = P_k^0 dM/dP_k; empty matrix if !affects_mass(k). */
    const SparseMatrix<double> &
    mass_derivative(const unsigned int k) const;

    /** K0 and M0, the nominal matrices. */
    const SparseMatrix<double> &
    nominal_stiffness() const;
    const SparseMatrix<double> &
    nominal_mass() const;

    /** Nominal moduli and densities of the zones. */
    const std::vector<double> &
    nominal_zone_moduli() const;
    const std::vector<double> &
    nominal_zone_densities() const;

    /**
     * Zone moduli and densities at the relative changes @p t (checked as in
     * perturbed_zone_materials()).
     */
    std::pair<std::vector<double>, std::vector<double>>
    zone_materials(const std::vector<double> &t) const;

    /**
     * K(t) and M(t), formed from the zone matrices (reinitialised on the
     * component's sparsity pattern).
     */
    void
    matrices(const std::vector<double> &t,
             SparseMatrix<double>      &K,
             SparseMatrix<double>      &M) const;

    /**
     * dst = sum_k c_k K_k x (the stiffness change in the direction c, for
     * which K(t) = K0 + sum_k t_k K_k); returns false and leaves dst zero if
     * no parameter with c_k != 0 affects K.
     */
    bool
    stiffness_change(const std::vector<double> &c,
                     const Vector<double>      &x,
                     Vector<double>            &dst) const;
    /** Same for the mass. */
    bool
    mass_change(const std::vector<double> &c,
                const Vector<double>      &x,
                Vector<double>            &dst) const;

  private:
    bool
    change(const std::vector<SparseMatrix<double>> &matrices,
           const std::vector<double>               &c,
           const Vector<double>                    &x,
           Vector<double>                          &dst,
           const MaterialProperty                   property) const;

    const Component                  &component_;
    std::vector<ReanalysisParameter>  parameters_;
    std::vector<double>               nominal_values_;
    std::vector<double>               nominal_moduli_;
    std::vector<double>               nominal_densities_;
    SparseMatrix<double>              K0_, M0_;
    std::vector<SparseMatrix<double>> K_, M_;
  };
} // namespace FuzzyContact

#endif
