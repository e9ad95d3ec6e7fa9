#pragma once
// Tail probabilities the significance tests need. Upper tails are computed
// directly, never as 1 - CDF, so small p-values keep their digits.

namespace hystbench::stats {

// Phi(z), the standard normal CDF.
double normal_cdf(double z);
// 2 (1 - Phi(|z|)), from erfc so that it does not round to 0 for large |z|.
double normal_two_sided_p(double z);

// Regularised incomplete beta I_x(a, b), a, b > 0, x in [0, 1]: the
// continued fraction of Numerical Recipes (Press et al., 3rd ed., 2007,
// section 6.4) evaluated by the modified Lentz method, with the symmetry
// I_x(a, b) = 1 - I_{1-x}(b, a) for x > (a + 1) / (a + b + 2), where the
// fraction converges fast. Throws std::invalid_argument outside the domain.
double incomplete_beta(double a, double b, double x);

// P(X > f) for X ~ F(d1, d2), d1, d2 > 0: I_{d2/(d2 + d1 f)}(d2/2, d1/2).
// 1 for f <= 0, 0 for f = +inf.
double f_survival(double f, double d1, double d2);

// Regularised lower incomplete gamma P(a, x) = γ(a, x)/Γ(a) and its
// complement Q(a, x) = 1 − P(a, x), a > 0, x ≥ 0: series for x < a + 1,
// continued fraction (modified Lentz) otherwise, so neither loses accuracy
// in its tail.
double gamma_p(double a, double x);
double gamma_q(double a, double x);
// P(X > x) for X ~ χ²(k).
double chi_squared_survival(double x, double k);

}  // namespace hystbench::stats
