#pragma once
// The natural rules of Nystad ch. 3 and app. B: da Vinci / Murray radii and Murray's branch angles.
// r0 = parent radius arriving at the branch point, r1 = primary (continuing), r2 = secondary (child).

namespace arbor::natural {

// C_p = 1 / (1 + S^E)^(1/E): primary radius over parent radius.
double primaryRadiusFactor(double S, double E);
// C_s = S / (1 + S^E)^(1/E): secondary radius over parent radius.
double secondaryRadiusFactor(double S, double E);

// n equal clones each get r / n^(1/E), so n r_c^E = r^E.
double cloneRadiusFactor(int n, double E);

// Murray's equilibrium (radians): angle of the primary from the parent direction,
// cos x = (r0^4 + r1^4 - r2^4) / (2 r0^2 r1^2).
double primaryAngle(double r0, double r1, double r2);
// ... and of the secondary, cos y = (r0^4 + r2^4 - r1^4) / (2 r0^2 r2^2).
double secondaryAngle(double r0, double r1, double r2);

// x + y from S and E alone: cos(x + y) = ((1 + S^E)^(4/E) - 1 - S^4) / (2 S^2).
double totalAngle(double S, double E);

// n equal clones spread symmetrically: each leaves the parent axis at theta with
// r0^2 = n r_c^2 cos(theta), so cos(theta) = n^(2/E - 1) (n = 2 is Murray's equal split).
double cloneAngle(int n, double E);

}  // namespace arbor::natural
