#ifndef AGAA_EPSILON_GLSL
#define AGAA_EPSILON_GLSL
// Every guard in shader math uses one of these named constants; tests drive
// each to its edge (tests/gpu/test_shader_math). Units in the comments.

// Smallest GGX alpha (= roughness^2): roughness 0 would make D a delta and
// D*G/(4 N.L N.V) divide by zero. 1e-3 keeps D finite (about 3.2e5 peak) in fp32.
const float kMinGgxAlpha = 1.0e-3;
// An aggregate's filtered alpha within this relative distance of kMinGgxAlpha is at that floor
// (common/environment.glsl environmentAggregateRoughness): fp32 rounding of sqrt(ax ay) for an
// SGGX lobe clamped on both axes stays far inside it.
const float kGgxAlphaFloorRelative = 1.0e-3;
// Largest GGX alpha of the shared BRDF (roughness 0.949). Toksvig encodes roughness as the
// length of the normal (shared/ag_buffer.h); alpha = 1 would be length 0 and erase the sample's
// direction from its aggregate's mean normal. Capping alpha for every method keeps each
// sample's normal with weight >= 0.32 while the methods still shade identically.
const float kMaxGgxAlpha = 0.9;
// Lower bound of N.V and N.L in the specular denominator 4 N.L N.V (grazing angles).
const float kMinCosine = 1.0e-4;
// Squared distance floor for inverse-square falloff (m^2): a light inside the
// geometry (distance -> 0) stays finite.
const float kMinLightDistance2 = 1.0e-4;
// Length below which a vector is treated as zero and a fallback is used
// (zero normals, cancelled tangents).
const float kMinNormalLength = 1.0e-6;
// Spot cone: cos(inner) - cos(outer) floor, so equal inner and outer cones do not divide by zero.
const float kMinSpotCosRange = 1.0e-4;
// Aggregate specular (common/brdf.glsl flakeWeight): the microflake form's weight ramps from 0 at
// spread 1 (one normal: a flat pixel keeps the microfacet form, its Smith masking and its horizon,
// so a light just below a flat mirror's horizon cannot leak through the lobe's peak) to 1 at spread
// 1 - kFlakeSpreadRange (unitless mean normal length). 0.1: a tube seen side-on has 0.79; the
// rounding of a flat aggregate's fixed-point normal moves its spread by under 1e-4.
const float kFlakeSpreadRange = 0.1;
// Largest radiance a tone mapper is fed; beyond it the curve is flat anyway and
// fp32 products would overflow (1e4 emissive * 1e3 light count stays below).
const float kMaxRadiance = 6.0e4;
// Simple/Complex depth test (relative to view distance): floor under the plane-slope
// tolerance, since a face-on plane has zero slope but its samples' fp32 depths still
// differ by interpolation and reconstruction rounding (about 1e-6 relative).
const float kDepthCompareRelative = 1.0e-4;
// SGGX eigen-decomposition (shared/sggx.h sggxLobe): the floor of the traces its squarings divide
// by, and the squared length below which a vector has no direction. The matrix entries are means
// in [-1, 1] with trace >= 1; a trace of 1e-12 is a zero matrix, and a tangent vector of squared
// length 1e-12 comes from tangent eigenvalues equal to 1e-6 (alphas equal to 1e-6 / lambda_n),
// where any axis of the plane gives the same lobe.
const float kSggxDegenerate = 1.0e-12;
// Floor of the SGGX normal's eigenvalue (the alphas divide by it). Any mean of sample matrices
// has trace >= 1 and so a largest eigenvalue >= 1/3; only corrupt input reaches the floor.
const float kMinSggxEigenvalue = 0.25;
// AGAA shadow footprint (common/depth.glsl aggregateWidth): a tangent direction whose screen
// projection (its view-space xy, squared length) is at or below this runs along the view ray and
// has no screen direction to measure the aggregate's samples along; the whole pixel is used.
const float kMinScreenDirection2 = 1.0e-6;
// Two-point tone mapping (agaa/lighting.comp): below this specular radiance an aggregate has no
// highlight to spread, and the spike (S^2 + var) / S would divide by ~0.
const float kMinSpikeRadiance = 1.0e-8;
// Face normal from screen-space derivatives (common/face_normal.glsl): below this sine of the
// angle between dP/dx and dP/dy the derivatives are parallel (a sliver seen edge-on) and the
// primitive has no plane to take a normal from. fp32 rounding of the derivatives gives a sine
// error near 1e-7; a real triangle, even at grazing angles, is far above 1e-6.
const float kMinFaceNormalSine = 1.0e-6;
// Curvature roughness (common/curvature_roughness.glsl): a quad-normal variance below this is
// interpolation rounding, not curvature. A flat face's interpolated unit normals differ by fp32
// rounding (about 1e-7 per component, so a variance near 1e-14); the bias it would add is invisible
// anyway (alpha^2 + 2e-10).
const float kMinCurvatureVariance = 1.0e-10;
// Near-mirror view footprint (common/depth.glsl viewFootprintWeight): where the half vector's slope
// variance over an aggregate's footprint, from the view direction alone, exceeds this share of its
// GGX lobe's, the lobe's peak is narrower than the pixel and one view direction no longer stands
// for the samples'; the blend to their own view directions ramps in from it to twice it. A quarter:
// the footprint's half-vector spread is half the lobe's width (a rough lobe, alpha >= 0.05, stays
// below it at any resolution here: 64x64 at 40 degrees gives theta^2 (sxx + syy) / 4 ~ 5e-6).
const float kViewFootprintLobeRatio = 0.25;

#endif
