// The internals of ReducedOrderModel (reduced_order_model.h), shared by
// its files, and not a public header: how each component's materials enter
// the reduced model (reduced_order_model.cc builds it,
// reduced_order_model_reanalysis.cc re-analyses its zone materials).

#ifndef fuzzycontact_study_reduced_order_model_component_h
#define fuzzycontact_study_reduced_order_model_component_h

#include <fuzzycontact/study/reduced_order_model.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  // Copies the block [rows, columns) of @p A.
  inline FullMatrix<double>
  block(const FullMatrix<double> &A,
        const unsigned int        row_begin,
        const unsigned int        n_rows,
        const unsigned int        column_begin,
        const unsigned int        n_columns)
  {
    FullMatrix<double> B(n_rows, n_columns);
    for (unsigned int i = 0; i < n_rows; ++i)
      for (unsigned int j = 0; j < n_columns; ++j)
        B(i, j) = A(row_begin + i, column_begin + j);
    return B;
  }


  // How a component's materials enter the reduced model.
  struct ReducedOrderModel::ComponentModel
  {
    // Exact scaling, or the parameter-independent HPTP.
    bool                       hptp = false;
    std::vector<SceneQuantity> quantities; // its varying material quantities
    std::vector<double>        nominal_moduli, nominal_densities;

    ModalBasis modes;
    // The basis and its reduced matrices (on the rank that built it: every
    // rank unless the components are spread over the ranks) and its sizes
    // (on every rank).
    std::shared_ptr<ReducedComponent> reduced;
    unsigned int             n_modes = 0, n_corrections = 0, n_added = 0;
    ReducedComponentMatrices nominal_matrices;
    // The static correction enters as a fixed residual flexibility.
    bool split = false;

    // The static correction re-analysed by Krylov vectors (zone correction
    // = krylov, or a model made richer by snapshots), on the rank that
    // built it, and the names of its parameters (the modulus quantities).
    std::unique_ptr<ZoneStaticCorrection> zone;
    std::vector<SceneQuantity>            zone_quantities;
    std::string                           zone_description;
    // (no modes, for a static correction without them)
    ModalBasis no_modes;

    // HPTP: the reanalysis and the projections that turn Y(p) into the
    // component's reduced matrices.
    std::unique_ptr<ParameterIndependentReanalysis> reanalysis;
    // (on the rank that built it) and its order and basis size (on all)
    unsigned int reanalysis_order = 0, reanalysis_vectors = 0;
    std::vector<FullMatrix<double>> T_K_psi;    // T^T K_z Psi per zone
    std::vector<FullMatrix<double>> psi_K_psi;  // Psi^T K_z Psi per zone
    FullMatrix<double>              C_T, C_psi; // C T, C Psi
    FullMatrix<double>              O_T, O_psi; // rows at observed DoFs
    std::vector<Vector<double>>     T_f, psi_f; // T^T f_l, Psi^T f_l
  };
} // namespace FuzzyContact

#endif
