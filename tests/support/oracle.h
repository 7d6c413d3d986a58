// Exact rational oracle for the predicates of kernel/predicates.h, on GMP integers (tests only).
//
// Every function mirrors the polynomial its namesake in delpsc::kernel is documented to compute
// (for the lower-dimensional power tests and the 4-argument coplanar_orientation: CGAL's
// power_side_of_oriented_power_sphereC3 and coplanar_orientationC3 in
// CGAL/predicates/kernel_ftC3.h, projection order included) and returns its exact sign.
//
// Method: a double is m * 2^e exactly (std::frexp). All inputs of one call are multiplied by one
// power of two 2^-E (weights by 2^-2E) chosen so that every one becomes an integer; each
// polynomial is homogeneous (coordinates degree 1, weights degree 2), so its sign is unchanged,
// and the evaluation runs on mpz integers, which is several times faster than on rationals.
// Determinants are expanded by one generic routine (Laplace expansion over row subsets), not by
// the hand-unrolled cofactors of the implementation.
//
// The perturbed oracles do not restate the implementation's tie-break rules: they build the
// determinant of the homogeneous (lifted) matrix with each weight replaced by w_i - eps^(n-rank_i)
// (rank_i = rank of point i among the n in lexicographic xyz order, from 0), expand it as a
// polynomial in eps with integer coefficients, and return the sign of the first non-zero
// coefficient (lowest power of eps first), as Devillers & Teillaud define the scheme.
//
// Inputs are pointers to 3 doubles (points) or 4 doubles (weighted points: x, y, z, w), exactly as
// the kernel's predicates take them. Not thread-safe (static scratch space).
#pragma once

namespace delpsc::test::oracle {

int compare_xyz(const double* p, const double* q);
int orient3d(const double* p, const double* q, const double* r, const double* s);
int orient2d(const double* p, const double* q, const double* r, int i, int j);
int coplanar_orientation(const double* p, const double* q, const double* r);
int coplanar_orientation(const double* p, const double* q, const double* r, const double* s);
bool collinear(const double* p, const double* q, const double* r);
int insphere(const double* p, const double* q, const double* r, const double* s, const double* t);
int power_test(const double* p, const double* q, const double* r, const double* s,
               const double* t);
int power_test(const double* p, const double* q, const double* r, const double* t);
int power_test(const double* p, const double* q, const double* t);
int power_test(const double* p, const double* q);
int power_distance_sign(const double* x, const double* c);
int compare_power_distance(const double* x, const double* p, const double* q);

/// Result of a perturbed oracle: the sign, and the power of eps whose coefficient decided it
/// (0 = the unperturbed determinant was non-zero; k > 0 = the perturbation of the point of rank
/// n - k decided). sign = 0 only if every coefficient vanished (a violated precondition).
struct PerturbedSign {
  int sign = 0;
  int eps_power = 0;
};

/// Sign of -det[x y z |p|^2-w+eps^(5-rank) 1] over the rows p, q, r, s, t (CGAL's convention:
/// +1 = conflict for positively oriented p, q, r, s). Precondition: orient3d(p, q, r, s) != 0.
PerturbedSign power_test_perturbed(const double* p, const double* q, const double* r,
                                   const double* s, const double* t);
/// The same with all weights 0 (p..t are 3-double points).
PerturbedSign insphere_perturbed(const double* p, const double* q, const double* r,
                                 const double* s, const double* t);
/// Coplanar p, q, r, t, p, q, r not collinear: in the first projection A among xy, xz, yz where
/// p, q, r are not collinear, sign det[u v |p|^2-w+eps^(4-rank) 1] over rows p, q, r, t, times
/// orient2d_A(p, q, r). +1 = t in conflict with the power circle, whatever the orientation.
PerturbedSign power_circle_side_perturbed(const double* p, const double* q, const double* r,
                                          const double* t);
/// Collinear p != q and t: on the first axis a where p and q differ,
/// sign(p_a - q_a) * sign det[x_a |p|^2-w+eps^(3-rank) 1] over rows p, q, t.
PerturbedSign power_segment_side_perturbed(const double* p, const double* q, const double* t);

}  // namespace delpsc::test::oracle
