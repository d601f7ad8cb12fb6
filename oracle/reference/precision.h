// The oracle's precision model: every tolerance the comparator applies, each derived here, next to its constant,
// from the sub-pixel snap and the float error of both renderers (../shared/DESIGN.md, "The oracle's tolerance
// model").
// No constant was tuned to make a scene pass; each bound has its own tests (tests/oracle/precision_test.cpp,
// tests/oracle/sample_classifier_test.cpp: just inside a bound is allowed, just outside is not).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace raster::oracle {

// u, the unit roundoff of float (round to nearest): 2^-24.
inline constexpr double kFloatUnitRoundoff = 0x1p-24;

// gamma_n = n u / (1 - n u) bounds the relative error of n chained float roundings, and a k-term float dot
// product has |fl(a.b) - a.b| <= gamma_k |a|.|b| (Higham, "Accuracy and Stability of Numerical Algorithms", 3.1).
constexpr double float_gamma(int roundings) {
    return roundings * kFloatUnitRoundoff / (1.0 - roundings * kFloatUnitRoundoff);
}

// --- 1. The snap ---------------------------------------------------------------------------------------------
// raster rounds each screen coordinate of each vertex to the nearest multiple of 2^-snap_bits px, so a vertex
// moves by at most half a step in x and in y (max norm):
//     snap_displacement = 2^-(snap_bits + 1) px        (1/512 px at the default 8 bits)
// Every point of the snapped triangle is the same convex combination of the moved vertices as its preimage, so
// the affine map A from the exact to the snapped triangle moves no point by more than that. Consequences:
//  - coverage: if the max-norm ball of radius r around a sample lies inside the exact triangle, the map
//    x -> p + x - A(x) sends the ball into itself, so (Brouwer) A has a point mapping onto p: p is covered by the
//    snapped triangle too; and a sample covered by the snapped triangle but outside the exact one is joined to
//    its preimage (inside) by a segment of length <= r that crosses the boundary. Either way, coverage can only
//    differ within r of the exact triangle's boundary;
//  - interpolation: raster's screen-space barycentrics at p are the exact triangle's at q = A^-1(p), |q - p| <= r.
double snap_displacement(int snap_bits);

// --- 2. Float error of a vertex ------------------------------------------------------------------------------
// A vertex p of a mesh with model matrix M, seen through view V and projection P, in clip space:
//  - raster computes float(float(float(P V) M) p) with its own float P and V: three chained 4-term products, so
//    its clip position is within gamma_12 (|P| |V| |M| |p|) of what its matrices give, componentwise; how far its
//    float matrices are from the oracle's exact camera is camera_precision.h's bound, added to this one;
inline constexpr int kRasterTransformRoundings = 12;
//  - the oracle computes V (M p) in double from its own M (model_transform.h) and the scene's float p and rounds
//    each view-space coordinate to
//    float once for Embree: within u of it, plus double's own error (a few 1e-16, relative): gamma_2 of |V||M||p|
//    (P only rescales x and y, so gamma_2 |P||V||M||p| bounds it in clip units as well);
inline constexpr int kOracleTransformRoundings = 2;
//  - Embree's watertight (Pluecker) test, per edge: vertex sum and difference (2), a cross product (2), a dot
//    product with the direction (3); then the u, v, t divisions (1); the ray direction itself rounded to
//    float (1). Its answer is exact arithmetic on vertices moved by gamma_9 of their magnitudes (backward error).
inline constexpr int kEmbreeTestRoundings = 9;
// The two renderers err independently, so a vertex of one can be as far from the other's as the sum:
inline constexpr int kVertexRoundings = kRasterTransformRoundings + kOracleTransformRoundings + kEmbreeTestRoundings;

// The error bound (clip units, per component) of an original vertex whose magnitudes are
// |P| |V| |M| |(p, 1)|: gamma_23 times them (the float camera's error comes on top, camera_precision.h).
glm::dvec4 vertex_error(const glm::dvec4& magnitudes);

// THE ORACLE'S OWN PLANE. The exact geometry is the oracle's double view transform V (M p): each view-space vertex
// within gamma_8 in double (two chained 4-term products) of |V||M||p| of exact, so within delta in 2-norm, delta
// that bound's length. Each edge e_i = v_i - v_0 is then off by at most 2 delta, and the normal e1 x e2 by at most
// 2 delta (|e1| + |e2| + 2 delta); the ray-plane determinant dot(direction, normal), evaluated in double (gamma_4
// of |e1| |e2| |direction| more), by |direction| times their sum: the PLANE NOISE. Where the determinant is within
// it the double geometry cannot say where, or whether, the ray meets the plane (a triangle seen exactly end-on, or
// one whose vertices are collinear, whose normal is rounding noise): it has no exact hit there. For any triangle
// with an area it is a grazing angle of about 1e-14 rad.
inline constexpr int kOracleDoubleViewRoundings = 8;
constexpr double double_gamma(int roundings) { return roundings * 0x1p-53 / (1.0 - roundings * 0x1p-53); }
// The plane noise per unit length of the direction, for edges e1, e2 and a largest vertex magnitude |V||M||p|
// (2-norm of the componentwise bound).
double plane_noise(const glm::dvec3& edge1, const glm::dvec3& edge2, double vertex_magnitude);

// --- 3. Clipping ---------------------------------------------------------------------------------------------
// raster's clipper makes each new vertex as a + t (b - a) with t = d_a / (d_a - d_b). In float that is the two
// plane distances (2 roundings), their difference (1), the division (1), b - a (1), the product (1), the sum (1),
// and the pin of w to near (1): gamma_8 relative to |a| + |b|. (raster/geometry/clip.cpp computes it in double and
// rounds once to float before the pin: 2 roundings, well inside the float bound kept here.)
// The cut point also moves with its endpoints. With a' = a + da, b' = b + db and distances moved by
// dd_a = n.da, dd_b = n.db (n the plane's coefficients, |dd| <= eps = |n|.e for an endpoint error e):
//     cut' - cut = (1 - t') da + t' db + (t' - t)(b - a),    t' - t = (d_a dd_b - dd_a d_b) / ((d_a' - d_b')(d_a - d_b))
// so, d_a and d_b having opposite signs (|d_a - d_b| = |d_a| + |d_b|),
//     error(cut) <= max(e_a, e_b) + |dt| |b - a| + gamma_8 (|a| + |b|),
//     |dt| <= (|d_a| eps_b + eps_a |d_b|) / (|d_a - d_b| (|d_a - d_b| - eps_a - eps_b))
// (unbounded when eps_a + eps_b reaches |d_a - d_b|). |dt| |b - a| is about eps / sin(theta) for an edge crossing the
// plane at angle theta: a shallow crossing slides the cut point far along the plane, which inheriting the
// endpoints' errors alone misses.
inline constexpr int kClipStepRoundings = 8;
// One end of an edge being clipped: its exact clip position, error bound and magnitudes, and its exact signed
// distance to the plane with that distance's error bound (eps = |n|.e).
struct ClipEnd {
    glm::dvec4 clip{0.0}, error{0.0}, magnitudes{0.0};
    double distance = 0.0, distance_error = 0.0;
};
glm::dvec4 clip_step_error(const ClipEnd& a, const ClipEnd& b);

// --- 4. From clip space to the screen ------------------------------------------------------------------------
// A clip-space error e = (ex, ey, ez, ew) at a vertex whose exact clip position is c moves its screen position
// (x/w + 1) W/2 by at most W/2 (ex + |cx/cw| ew) / (cw - ew) in x, and H/2 (ey + |cy/cw| ew) / (cw - ew) in y
// (the numerator bounds the change of x w' - x' w over w w'). Infinite when ew >= cw.
glm::dvec2 screen_error(const glm::dvec4& clip, const glm::dvec4& error, int width, int height);

// The RADIUS of a triangle is r = snap_displacement + the largest screen_error of its clipped vertices (max norm):
// how far any vertex of raster's or the oracle's version of it can be from exact. The comparator uses it for:
//  - the EDGE BAND: a disagreement at a sample within r of an edge of an involved triangle is ambiguous, one
//    beyond r is genuine (section 1);
//  - the SPREADS: raster's barycentrics and depth at a sample p are the exact triangle's at some q within r of p
//    (section 1; a perturbed vertex is equivalent to a moved sample by the same argument). Perspective-correct
//    barycentrics and 1/w are linear-fractional in screen space, so over the max-norm square of half-side r
//    around p they take their extremes at its 4 corners: the spread of a value is max - min over the corners.

// --- 5. Depth ------------------------------------------------------------------------------------------------
// The RELATIVE DEPTH ERROR of a vertex, ew / (cw - ew): how far its 1/w (perspective weight) can be off,
// relatively. A triangle's is the largest over its clipped vertices.
double relative_depth_error(double w, double w_error);

// Perspective-correct barycentrics b_i = (l_i / w_i) / sum_k (l_k / w_k) with each 1/w_i off by a relative rel
// move by at most b_i 2 rel / (1 - rel) <= 2 rel / (1 - rel); one renderer then adds the float rounding of its
// clip-vertex barycentrics (a + t (b - a): 3 roundings) and of its result (1). Per renderer:
inline constexpr int kBarycentricRoundings = 4;
double barycentric_rounding(double relative_depth_error);

// View depth 1 / sum_k (l_k / w_k) with each 1/w_k off by a relative rel is off by at most rel / (1 - rel); then
// raster rounds 1/w_i to float (1) and the result to float (1), and Embree rounds t (1). Per renderer, relative:
inline constexpr int kViewDepthRoundings = 2;
double view_depth_rounding(double relative_depth_error);

// DEPTH TIES. raster's depth test compares reversed-Z d = z/w, interpolated linearly in screen space from float
// vertex values. A vertex's d is off by at most (ez + |d| ew) / (cw - ew) (as in section 4), then rounded to
// float (1), the interpolated d is rounded to float (1), and the oracle's choice between two surfaces rests on its
// t, rounded (1) and mapped to d (1): 4 roundings of a value in [0, 1]. A triangle's reversed-Z error:
inline constexpr int kReversedZRoundings = 4;
double reversed_z_error(const glm::dvec4& clip, const glm::dvec4& error);
// Two surfaces TIE at a sample when their reversed-Z intervals over the r-square (corner extremes, widened by each
// triangle's reversed-Z error and by Embree's view-depth error at the sample mapped to d, "Embree's view depth"
// below) overlap: then either renderer may legitimately show either.

// EMBREE'S BARYCENTRICS. The backward-error view of Embree's test (section 2) holds edge by edge, not for the
// barycentrics: Embree (robust mode: the Pluecker test) computes, with the ray origin at the eye and vertices
// v0, v1, v2 relative to it, U = dot(cross(v2 - v0, v2 + v0), D) and likewise V (edge v0 -> v1) and W, each with
// its own rounding, then u = U * rcp(U + V + W) and v = V * rcp(U + V + W). With the magnitude
//     M_U = dot(|v2 - v0| x| |v2 + v0|, |D|)        (x|: the cross product's two products added, not subtracted)
// the difference (1), sum (1), cross product (2), dot product (3) and the float ray direction (1) bound
// |fl(U) - U| <= gamma_8 M_U =: E_U. The sum adds 2 roundings: E_S = gamma_10 (M_U + M_V + M_W). Then
//     |fl(u) - u| <= (E_U + |u| E_S) / (|S| - E_S) + gamma_7 |u|
// where S = U + V + W is exact and gamma_7 covers Embree's reciprocal (an estimate refined by one Newton step:
// 6 roundings) and the product (1); the oracle then forms 1 - u - v in float (2). For a well-shaped triangle this
// is a few float roundings; for a needle, S (twice its area, seen along D) is small next to M and the error grows
// as M / S: raster's snapped barycentrics move with the snap (the spreads), Embree's with this.
inline constexpr int kEmbreeEdgeRoundings = 8;
inline constexpr int kEmbreeSumRoundings = 2;
inline constexpr int kEmbreeRatioRoundings = 7;
inline constexpr int kOracleBarycentricRoundings = 2;
// The bound per component (1 - u - v, u, v), for view-space vertices `v`, ray direction `direction` and exact
// barycentrics `bary` at the sample; infinite when E_S >= |S| (Embree's answer is then unconstrained).
glm::dvec3 embree_barycentric_error(const glm::dvec3 v[3], const glm::dvec3& direction, const glm::dvec3& bary);

// EMBREE'S VIEW DEPTH. Embree computes t from the oracle's float vertices as T / den with Ng the cross product of
// two edges, den = 2 dot(Ng, D) and T = 2 dot(v0, Ng) (the eye at the origin; the bound takes the worst pair of
// edges, so it does not depend on which two Embree takes). With the exact edges a, b, their
// float versions are off by the vertex errors of their ends plus one rounding; the cross product's change is
// |da| x| |b'| + |a| x| |db| and its own rounding gamma_2 |a'| x| |b'| (x|: products added); den and T add the
// float direction (u) and their dot products (gamma_3); then
//     |t' - t| <= (E_T + |t| E_den) / (|den| - E_den) + gamma_7 (|t| + that)
// (gamma_7: Embree's reciprocal, refined once, times T). For a triangle seen almost edge-on, den (twice its
// area seen along D) is small and the error grows as 1 / den: the differential fuzzer found Embree's depth 0.3%
// off on a sliver. Infinite when E_den >= |den|.
inline constexpr int kEmbreeCrossRoundings = 2;
inline constexpr int kEmbreeDotRoundings = 3;
double embree_view_depth_error(const glm::dvec3 v[3], const glm::dvec3 error[3], const glm::dvec3& direction,
                               double view_depth);

// EMBREE'S COVERAGE. Embree decides a ray's hit from the signs of U, V and W: all >= -eps, or all <= eps, with
// its own slack eps = ulp |U + V + W| (ulp = 2u). Each sign is exact for vertices moved by a little (section 2),
// but the moves differ from edge to edge, so Embree's coverage is not that of any one moved triangle: it is the
// set of rays within each edge's own uncertainty of that edge's plane through the eye. For a fat triangle that is
// the edge band; for a needle, whose long edges run along one line, it reaches along that line beyond the tip;
// for a triangle whose edges all pass within float error of the eye, it is every ray. With the exact vertices
// v_i, the oracle's float vertices within e_i of them (gamma_8 of |V| |M| |p|, section 2), U = 2 dot(v2 x v0, D)
// changes with the vertices by at most 2 (dot(|e_2| x| (|v0| + |e_0|), |D|) + dot(|v2| x| |e_0|, |D|)) and its
// float evaluation adds gamma_8 M_U; so with B_U their sum, Embree may report a hit only when, for one sign s,
//     s U >= -(B_U + eps_max), s V >= -(B_V + eps_max), s W >= -(B_W + eps_max)
// where eps_max = 2u (1 + gamma_3) (|U| + |V| + |W| + B_U + B_V + B_W) bounds Embree's slack. The comparator uses
// this for a sample where the oracle shows a triangle that exactly does not cover it (section 4's band aside):
// when Embree may cover the sample, the disagreement is ambiguous (EDGE BAND).
// The other way round, Embree may MISS a triangle that exactly covers the sample unless, for one sign s, every
// s U >= B_U (then Embree's U is of that sign, and its slack only widens what it accepts). That is again the edge
// band for a fat triangle; for a triangle with a vertex far out (the differential fuzzer found one at 5e5 beside
// vertices of magnitude 10), the B of its two edges through that vertex is large against the values they take
// near the other vertices, and Embree missed a sample 3e-4 (in barycentrics) inside such an edge, beyond the band.
// The comparator uses it where raster shows a triangle that exactly covers the sample and the oracle does not.
glm::dvec3 embree_edge_uncertainty(const glm::dvec3 v[3], const glm::dvec3 error[3], const glm::dvec3& direction);
bool embree_may_cover(const glm::dvec3 v[3], const glm::dvec3 error[3], const glm::dvec3& direction);
bool embree_may_miss(const glm::dvec3 v[3], const glm::dvec3 error[3], const glm::dvec3& direction);

// --- 6. Clip boundary ----------------------------------------------------------------------------------------
// raster's near and far clip edges sit where its float w crosses the plane: within the triangle's largest
// clip-space w error (absolute, the DEPTH ERROR) of the exact plane, and then are snapped (r). A sample is on
// the clip boundary of a triangle when the triangle's view-depth interval over the r-square, widened by the depth
// error, contains near or far, and the r-square reaches the triangle (every barycentric's corner maximum >= 0).
// THE EYE. A point at clip w with w <= E_w (the largest w error of the triangle's vertices) has no bounded screen
// position (section 4: the denominator w - E_w is not positive). When the near plane is that close to the eye
// (near <= 2 E_w) and some point of the triangle may be kept there by either renderer (w >= near - E_w, and
// inside the side planes widened by the errors: |x| <= w + E_x + E_w, likewise y), the triangle's footprint is
// unbounded: a triangle whose plane passes within E_w of the eye covers, in float, any sample at a depth of that
// order. Its radius is then infinite, so every disagreement it is part of is ambiguous. The differential fuzzer
// found both directions: a triangle with an edge through the eye, exactly seen edge-on and covering nothing, hit
// by Embree at depth 9e-9; and one covered by raster at such depths where Embree saw nothing.

// --- 7. Facing ----------------------------------------------------------------------------------------------
// With back-face culling, raster keeps a triangle when det[x y w] of its three float clip-space vertices is > 0
// (raster/setup.h faces_front); the oracle decides from the sign of the same determinant's view-space counterpart
// (a linear map of it). Each renderer's rows are the exact rows c_i moved by d_i with |d_i| <= e_i componentwise
// (section 2). The determinant is multilinear in its rows, so det(C + D) - det(C) is a sum of determinants each
// with at least one row taken from D; Hadamard bounds each by the product of its rows' 2-norms, and the sum is
//     |det(C + D) - det(C)| <= prod_i (|c_i| + |e_i|) - prod_i |c_i|            (2-norms of (x, y, w))
// raster evaluates its determinant in double from float inputs (exact 2x2 products, then 4 roundings):
// gamma_4(double) prod_i |c_i + e_i|_1 bounds that. Where |det(C)| is within the sum, the renderers may decide the
// triangle's facing differently, and every disagreement it is involved in is ambiguous (FACING).
inline constexpr int kFacingDoubleRoundings = 4;
double facing_uncertainty(const glm::dvec4 clip[3], const glm::dvec4 error[3]);
// True when the exact clip-space vertices' determinant is within facing_uncertainty of 0.
bool facing_is_uncertain(const glm::dvec4 clip[3], const glm::dvec4 error[3]);

// --- 8. Colour -----------------------------------------------------------------------------------------------
// Both renderers' colours come from the same shader applied to (triangle, barycentrics). On agreeing samples, the
// colour raster's pipeline gives at raster's own (triangle, barycentrics) must equal, byte for byte, what the
// reference shader gives at the same inputs: the same function of the same inputs is deterministic, so the
// tolerance is 0 output levels. Colour differences caused by barycentrics are judged by the barycentric bound.
inline constexpr int kColorToleranceLevels = 0;

}  // namespace raster::oracle
