// Test seam for the proof's mutation tests (tests/enclose_proof_mutation_test.cpp,
// docs/proofs.md): deliberate faults that the proof's tests must catch. Only a
// program compiled with VISCOR_PROOF_MUTATIONS can switch one on; everywhere else
// proof_mutated() is a constant false, so the faulty branches are dead code that the
// compiler removes, and a release build neither exposes the seam nor changes.
//
// Define VISCOR_PROOF_MUTATIONS in a program's every translation unit or in none
// (the proofs are header-only: one definition per program).
#pragma once

namespace viscor::proofs {

/// The faults the proof's mutation tests can switch on (one at a time).
enum class proof_mutation {
  none,                  ///< the proof as it is
  remainder_scaled,      ///< validated_step: the remainder multiplied by proof_mutation_factor() (< 1)
  remainder_from_point,  ///< validated_step: the remainder from the initial state's jet, not the a priori box
  box_test_skipped,      ///< validated_step: the first candidate box accepted without the inclusion test
  crossing_unproven,     ///< enclose_crossing_in: no proof of the end points' signs and of the slope's sign
};

#ifdef VISCOR_PROOF_MUTATIONS
/// The mutation switched on in this thread, and the factor of remainder_scaled.
struct proof_mutation_state {
  proof_mutation active = proof_mutation::none;  ///< the fault in effect
  double factor = 1;                             ///< the remainder's factor under remainder_scaled
};
/// The seam's state (only with VISCOR_PROOF_MUTATIONS).
inline thread_local proof_mutation_state proof_mutation_seam;
/// Whether fault m is switched on.
inline bool proof_mutated(proof_mutation m) { return proof_mutation_seam.active == m; }
/// The remainder's factor under proof_mutation::remainder_scaled.
inline double proof_mutation_factor() { return proof_mutation_seam.factor; }
#else
/// Whether fault m is switched on: never without VISCOR_PROOF_MUTATIONS.
constexpr bool proof_mutated(proof_mutation) { return false; }
/// The remainder's factor under proof_mutation::remainder_scaled: 1 without VISCOR_PROOF_MUTATIONS.
constexpr double proof_mutation_factor() { return 1; }
#endif

}  // namespace viscor::proofs
