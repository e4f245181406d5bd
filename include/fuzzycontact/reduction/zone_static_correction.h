// The static correction of a component whose zone moduli change, re-analysed
// by Krylov (combined-approximations) vectors, so that the reduced contact
// flexibility follows the zone's modulus instead of staying at its nominal
// value.
//
// With the stiffness affine in the relative changes t_k of the parameters,
// K(t) = K0 + sum_k t_k K_k (reanalysis/reanalysis_parameters.h), the exact
// response to the boundary columns E (unit loads at the contact DoFs and
// the component's loads, reduced_component.h) has the Neumann series
//
//   K(t)^{-1} E = sum_j (-1)^j (sum_k t_k K0^{-1} K_k)^j K0^{-1} E,
//
// so it lies, to high accuracy, in the block Krylov space spanned by
//
//   R_0 = K0^{-1} E,   R_j = K0^{-1} K_k R_{j-1}  (every k),  j = 1 .. s,
//
// each column one back-substitution with the factorisation of K0 the model
// already holds. The Galerkin projection onto that space does far better
// than the series (the best approximation in the energy norm; for a zone
// modulus the eigenvalues of K0^{-1} K_k lie in [0, 1], and the many at 0
// and 1, the directions away from the zone and inside it, cost nothing).
//
// The basis is V = [Psi, Z]:
//  - Psi = K0^{-1} E X, the nominal static correction (K0-orthonormal, as
//    in reduced_component.h), never formed: V^T K0 x = X^T E^T x, and
//    Psi c = K0^{-1} (E X c) is one back-substitution;
//  - Z, explicit vectors K0-orthogonal to Psi (so zero where E has its
//    unit columns: C Z = 0) and K0-orthonormal: the modes and their HPTP
//    terms if the study computes modes, the compressed Krylov levels, and
//    snapshots (add_vectors(): exact displacement fields where a proof of
//    a bound failed).
// Psi^T K_k Psi = X^T E^T (K0^{-1} K_k Psi) comes from the rows at the
// boundary of the first Krylov block, so no product of full-length blocks
// with many columns is ever formed.
//
// Compression. Level by level, the new block is made K0-orthogonal to V
// (Psi through E, Z by classical Gram-Schmidt twice) and compressed by a
// proper orthogonal decomposition (the eigen-decomposition of its K0 Gram
// matrix): directions whose K0-norm times the largest |t|^j over the box is
// below sqrt(tolerance) / 10 are dropped, and only the kept directions are
// multiplied again (the contact flexibility error of a Galerkin projection
// is the square of its energy error). The first level would have one
// column per column of E (hundreds), and Psi^T K_k Psi needs them all: it
// is probed instead by l random combinations Omega of the static
// correction's columns (a randomised range finder): K0^{-1} K_k Psi Omega
// gives the first Krylov block's range and, through its rows at the
// boundary, M Omega with M = Psi^T K_k Psi, whose Nystrom approximation
// (M Omega) (Omega^T M Omega)^+ (M Omega)^T is exact once l exceeds M's
// numerical rank. l starts at 32 and doubles while it does not exceed
// that rank with room to spare, or while the contact flexibility misses
// the tolerance; from l = n_s / 2 on, Omega = I (all of it, exactly). A
// zone away from the contact gives M a small numerical rank (Saint-Venant:
// a few probes), a zone under it a large one.
// Levels are added until the relative error of the component's contact
// flexibility W_c = C_c K^{-1} C_c^T and of its load gaps, measured against
// exact factorisations at every corner of the parameter box, meets the
// tolerance (or the highest level is reached, or nothing new comes: then
// check().tolerance_met is false, and the model's description says so).
//
// Online. Only the span of the parameters' projections A_k = V^T K_k V
// changes with t (V^T K0 V = I): a pivoted Cholesky factorisation of
// sum_k A_k (PSD) splits V into an active part Q_a (its numerical range)
// and an inert part Q_c on which K_r(t) = I for every t. The inert part's
// blocks are formed once (fixed_matrices()); per state only the active
// part changes (matrices()):
//  - one parameter: Q_a^T A_1 Q_a is diagonalised once, so the reduced
//    stiffness at t is the diagonal I + t Lambda: O(rows x active) per state
//    and no factorisation; the contact flexibility is exactly the Galerkin
//    one, (C V Y) (I + t Lambda)^{-1} (C V Y)^T + the inert part;
//  - several parameters: I + sum_k t_k Q_a^T A_k Q_a, a dense Cholesky of
//    the active size per state.
// A zone far from the contact leaves most directions inert (Saint-Venant),
// a zone under the contact few.

#ifndef fuzzycontact_reduction_zone_static_correction_h
#define fuzzycontact_reduction_zone_static_correction_h

#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>
#include <fuzzycontact/reduction/reduced_component.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace FuzzyContact
{
  struct ZoneCorrectionSettings
  {
    /**
     * The relative error of the component's contact flexibility and load
     * gaps at the corners of the parameter box (Frobenius norm of the
     * difference from the exact ones, over that of the exact ones) that the
     * Krylov vectors must reach.
     */
    double tolerance = 1e-8;
    /** The highest Krylov level s (powers of K0^{-1} K_k). */
    unsigned int max_degree = 8;
  };

  /** What the Krylov static correction is, and how exact at the corners. */
  struct ZoneCorrectionCheck
  {
    /** Krylov levels built, and the vectors of each kind in the basis. */
    unsigned int degree = 0, n_static = 0, n_modes = 0, n_krylov = 0,
                 n_snapshots = 0;
    /** Directions that change with the parameters (the rest are inert). */
    unsigned int n_active = 0;
    /**
     * The largest relative error over the corners of the box, of the
     * component's contact flexibility and of its load gaps (0 without
     * loads), and whether both met the tolerance.
     */
    double flexibility_error = 0, load_error = 0;
    bool   tolerance_met = false;
    /** Corners checked (exact factorisations made for the check). */
    unsigned int n_corners = 0;
    /** Back-substitutions with the nominal factorisation offline. */
    unsigned long back_substitutions = 0;
    /** Probes of the static correction for the first level (see above). */
    unsigned int probes = 0;
  };

  class ZoneStaticCorrection
  {
  public:
    /**
     * Builds the basis of @p component for the modulus parameters
     * @p parameter_names (scene quantity names, e.g. "Foundation.grout.E"),
     * whose values range over @p ranges (absolute values); the component is
     * at its nominal materials. @p static_part: the component's nominal
     * static correction without modes (ReducedComponent, on the
     * factorisation of the nominal stiffness with the contact DoFs among
     * its trailing ones); @p modes: the modes and their HPTP terms to
     * include (may be empty). @p gap_operator: C_c; @p observed: the DoFs
     * whose displacements the model reports. Stages are timed in @p timer.
     */
    ZoneStaticCorrection(const Component                &component,
                         const std::vector<std::string> &parameter_names,
                         const std::vector<std::pair<double, double>> &ranges,
                         std::shared_ptr<const ReducedComponent> static_part,
                         const std::vector<Vector<double>>      &modes,
                         const SparseMatrix<double>             &gap_operator,
                         const std::vector<types::global_dof_index> &observed,
                         const ZoneCorrectionSettings               &settings,
                         TimerOutput *timer = nullptr);
    ~ZoneStaticCorrection();

    /** Number of basis vectors k. */
    unsigned int
    size() const;
    /** The basis and its accuracy at the corners (see above). */
    const ZoneCorrectionCheck &
    check() const;
    /** One line: levels, vectors of each kind, errors at the corners. */
    std::string
    describe() const;
    /** The parameter model (nominal values, relative changes, K_k). */
    const ParameterModel &
    model() const;

    /**
     * The reduced matrices of the active part at the parameter values
     * @p values (absolute, one per parameter, in the order of the
     * constructor): with one parameter a diagonal stiffness
     * (ReducedComponentMatrices::stiffness_diagonal), else a dense one. The
     * basis-independent fields are @p nominal's.
     */
    ReducedComponentMatrices
    matrices(const std::vector<double>      &values,
             const ReducedComponentMatrices &nominal) const;

    /**
     * The reduced matrices of the inert part (K_r = I whatever the
     * parameters), without the basis-independent fields (no weight, no
     * free motions: those are the active part's); empty (no columns) if
     * every direction is active.
     */
    ReducedComponentMatrices
    fixed_matrices(const ReducedComponentMatrices &nominal) const;

    /**
     * Adds the vectors @p u (e.g. exact displacement fields of the
     * component) to the basis, K0-orthogonalised against it; a vector whose
     * new part has a K0-norm below 1e-10 of its own is dropped. Returns how
     * many were added. The projections, the split and the check are
     * updated.
     */
    unsigned int
    add_vectors(const std::vector<Vector<double>> &u);

    /**
     * The relative error of the contact flexibility and of the load gaps at
     * the parameter values @p values against an exact factorisation there
     * (made for the call).
     */
    std::pair<double, double>
    error_at(const std::vector<double> &values) const;

  private:
    struct Data;
    std::unique_ptr<Data> data;
  };
} // namespace FuzzyContact

#endif
