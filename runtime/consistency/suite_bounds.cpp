#include "consistency_suite.hpp"

namespace iblkit::consistency {

// Each bound is twice the largest error measured on lavapipe (docs/consistency.md), rounded
// up; boundsRationale() says why the errors are what they are.
Bounds lutBounds(uint32_t size) {
    if (size <= 32) return {5e-5, 1.5e-6, 5e-5, 1.5e-6};
    return {1.2e-2, 4e-5, 2e-3, 6e-6};
}

Bounds quadratureLutBounds() { return {5e-6, 3e-7, 8e-6, 6e-7}; }
Bounds lutFitBounds() { return {2.4e-7, 3.6e-8, 1e-6, 1.5e-7}; }
Bounds lutGridBounds() { return {2.3e-6, 2.2e-7, 4.6e-6, 6.4e-7}; }
Bounds lutResampleBounds() { return {1.2e-6, 2.2e-7, 1.4e-6, 2e-7}; }

Bounds prefilterBounds() { return {1.5e-3, 2e-5, 1.5e-3, 6e-5}; }

Bounds lutChunkBounds() { return {5e-5, 2e-6, 4e-5, 1e-6}; }
Bounds prefilterChunkBounds() { return {4e-4, 1.2e-5, 4e-4, 1.2e-5}; }
Bounds skyBounds() { return {2.6e-1, 6.8e-3, 2.6e-1, 6.8e-3}; }
Bounds equirectBounds() { return {3.2e-2, 2.3e-3, 3.2e-2, 2.3e-3}; }
Bounds downsampleBounds() { return {8e-6, 4e-7, 8e-6, 4e-7}; }
Bounds shBounds() { return {1.6e-4, 1.1e-4, 1.6e-4, 1e-4}; }
Bounds irradianceBounds() { return {1e-5, 1e-6, 1e-5, 1e-6}; }
Bounds clusterBounds() { return {2.4e-4, 8e-6, 2.4e-4, 8e-6}; }
Bounds convolutionBounds() { return {1.4e-5, 1.1e-6, 1.4e-5, 1.5e-6}; }
Bounds filteredBounds() { return {1.4e-3, 1.1e-5, 1e-3, 6e-5}; }
Bounds tableBounds() { return {1.8e-4, 1.7e-6, 1e-3, 6e-5}; }
Bounds pyramidBounds() { return {1.6e-5, 5e-7, 1.7e-5, 5.3e-7}; }
Bounds ringBounds() { return {3.8e-6, 2.7e-7, 4.8e-6, 3e-7}; }

// The rows expected to fail, with why: none now (boundsRationale() says which one was).
std::string knownDivergence(const std::string&, const std::string&) { return {}; }
Bounds previewBounds() { return {1e-6, 1e-7, 1e-6, 1e-7}; }
Bounds pbrProbeBounds() { return {1.4e-6, 1.5e-7, 1.1e-6, 1.6e-7}; }
Bounds lutProbeBounds() { return {1.2e-6, 2.4e-7, 2.4e-6, 6e-7}; }
Bounds bsdfProbeBounds() { return {5.3e-6, 2.2e-7, 3.8e-6, 1.9e-7}; }
Bounds renderReferenceBounds() { return {9.4, 9.4e-2, 9.4, 9.4e-2}; }
Bounds splitSumSpheresBounds() { return {2e-5, 4.6e-7, 2e-5, 4.6e-7}; }
Bounds forwardPassBounds() { return {0.21, 1.3e-2, 0.21, 1.3e-2}; }

std::string boundsRationale() {
    return "Every bound is twice the largest error measured on lavapipe, rounded up; a row must keep both its largest "
           "absolute error and its RMS error within them, against both references.\n\n"
           "- **LUT 32²** (max 5e-5, RMS 1.5e-6): values lie in [0, 1]. The GPU and the float reference do the same float "
           "operations, but llvmpipe's sqrt, sin, cos, pow and normalize differ from glibc's in their last bits; over "
           "1024 samples the GPU ends at most 2.2e-5 from either reference — the float reference itself is 2.6e-5 "
           "from the double one.\n"
           "- **LUT 512²** (max 1.2e-2 against float, 2e-3 against double; RMS 4e-5 and 6e-6): the 512² LUT has a "
           "column at N·V = 1/1024, where IntegrateBRDF is ill-conditioned: whether a sample's N·L is above 0 after "
           "the cancellation in 2(V·H)H − V depends on the last bits, and such a sample weighs G·V·H / (N·H·N·V), of "
           "order 1/N·V. The float reference, with glibc's rounding, is further from the double truth (6.9e-3) than "
           "the GPU is (9.6e-4), hence the wider bound against it. The RMS bounds stay tight: a porting bug moves "
           "every texel (k = (r+1)²/8 changes LUT values by 1e-2 and more at most roughnesses).\n"
           "- **Prefilter** (max 1.5e-3, RMS 2e-5 against float and 6e-5 against double): radiance reaches ~40 at the "
           "test sun; errors of 1e-5 relative come from float rounding of the 1024-sample sums (at roughness 0 all "
           "1024 samples are the same direction, so the float sum's rounding shows most against double) and from the "
           "texture unit's bilinear weights against the reference's exact ones. A swapped face or a transposed tangent "
           "frame moves texels by 1e-1 to 10.\n"
           "- **LUT in chunks** (max 5e-5 against float, 4e-5 against double; RMS 2e-6 and 1e-6): the same math as the "
           "LUT over the same 1024 samples, its float sums regrouped into chunks of 300 added through an RG32F image; "
           "measured 2.2e-5 and 1.8e-5, RMS 8.9e-7 and 4.7e-7 — the whole-loop LUT's errors, the regrouping adding "
           "less than the transcendental functions' last bits.\n"
           "- **Prefilter in chunks** (max 4e-4, RMS 1.2e-5, against both): measured 1.9e-4 and RMS 5.8e-6 at "
           "roughness 0.5, against 1.8e-4 for the whole-loop shader at the same roughness: the regrouped sums add "
           "rounding of the same order.\n"
           "- **SkyCube** (max 0.26, RMS 6.8e-3, against both): the checkered ground's cells change at every 15° "
           "of longitude, 45° among them, where the cube's face diagonals put evaluations exactly on a cell's "
           "edge: a last-bit difference in llvmpipe's atan2 puts them in the other cell, 0.26 darker or lighter, "
           "0.065 per evaluation of a texel's four; measured 0.13 (two of four), RMS 3.4e-3, the same with the "
           "sun's disc taken out. The float reference is 6.0e-5 from the double one, on values up to ~4000.\n"
           "- **BrdfLutQuadrature** (max 5e-6, RMS 3e-7 against float; 8e-6, 6e-7 against double), 128² at 7 nodes "
           "per panel: every path lands 2.4e-6 from the float twin, RMS 1.3e-7, on values up to 1; the float twin "
           "is 3.7e-6 from the double one (the method's own float rounding, mostly the ring integral's pole terms "
           "where roughness and N.V are both small), and the paths 3.8e-6, RMS 3e-7. The twin takes llvmpipe's "
           "place only where the shader uses transcendental functions llvmpipe gets to float precision (sin, cos, "
           "tan, log, sqrt); atan and asin, which llvmpipe has 2e-5 and 2e-4 off, are the shader's own (Cephes' atanf) "
           "in both; with llvmpipe's atan for the arc's length, every path fails (tests/consistency).\n"
           "- **BrdfLutGrid** (max 2.3e-6, RMS 2.2e-7 against float; 4.6e-6, 6.4e-7 against double), 32² nodes at 7 "
           "nodes per panel: the quadrature above at the grid's nodes, roughness a cube and N.V = s (2 - s) of a cube "
           "s, the ends included; measured 1.13e-6 from the float twin on every path and 2.3e-6 from the double one.\n"
           "- **BrdfLutResample** (max 1.2e-6, RMS 2.2e-7 against float; 1.4e-6, 2e-7 against double), 128² from "
           "the same 32² grid on every path: measured 5.4e-7 from the float twin and 6e-7 from the double one, "
           "on values up to 1 (float rounding of the cube roots and the 16-term sums; not split further); with the "
           "edge node repeated "
           "instead of extrapolated, every path fails (tests/consistency).\n"
           "- **BrdfLutFit** (max 2.4e-7, RMS 3.6e-8 against float; 1e-6, 1.5e-7 against double), the 128² LUT at "
           "degree 5 (36 terms): both references evaluate the fit's coefficients rounded to float, as "
           "Common/BrdfLutFit.fxh holds them, so the row measures the evaluation alone: measured 1.2e-7 (RMS 1.8e-8) "
           "from the float twin on the Vulkan paths and 0 on OpenGL, and 5e-7 (RMS 7.2e-8) from the double one, "
           "which is the float twin's own distance from it. A square root for N.V's fourth root fails every path.\n"
           "- **EquirectToCube** (max 3.2e-2, RMS 2.3e-3, against both): llvmpipe's acos is off glibc's by up to 1.6e-4 "
           "rad (measured over [-1, 1]), which moves a read by up to 3e-3 of a panorama texel in latitude; beside the "
           "test sun (radiance 40 over a few texels) that is 1.6e-2 (RMS 1.2e-3). The float reference is 1.2e-5 from "
           "the double one; with Cube.fxh's latitude written as atan2(length(d.xz), d.y) instead, the GPU lands "
           "2.2e-4 from both, so the bound covers acos alone. A swapped face moves texels by 1e-1 to 40.\n"
           "- **PrefilterFiltered, PrefilterTable and PrefilterPyramid**, 32² from the 64² test environment with its "
           "whole chain (1024 samples; the pyramid's two reads fitted at each roughness). The reference reads the chain "
           "as the texture unit does, bilinear and seamless, with the texel beyond a cube corner the mean of the three "
           "around it, as llvmpipe takes it: with one of the three instead, the pyramid's single reads were up to 1.0 "
           "off (4 %) at the corner nearest the test sun, and the sampled kernels 4.2e-3. Measured over the four "
           "roughnesses, the largest on any path: PrefilterFiltered 6.8e-4, RMS 5.2e-6, against float and 4.9e-4, RMS "
           "2.9e-5, against double (bounds 1.4e-3 / 1.1e-5 and 1e-3 / 6e-5); PrefilterTable 8.8e-5, RMS 8.4e-7, and "
           "the same against double (bounds 1.8e-4 / 1.7e-6 and 1e-3 / 6e-5); PrefilterPyramid 7.6e-6, RMS 2.5e-7, "
           "and 8.3e-6, RMS 2.6e-7 (bounds 1.6e-5 / 5e-7 and 1.7e-5 / 5.3e-7); PrefilterRing, at the roughnesses that "
           "take it (0.5 and 1), 1.9e-6, RMS 1.3e-7, and 2.4e-6, RMS 1.5e-7 (bounds 3.8e-6 / 2.7e-7 and 4.8e-6 / "
           "3e-7). The largest are at roughness 0, where "
           "every sample reads mip 0 along a direction rounded differently in float: the float reference is 4.9e-4 from "
           "the double one there and 4e-6 to 4e-5 elsewhere. Reading the lod with the natural log instead of log2 "
           "fails every path of the sampled kernels; a table summed without its N.L weights too; the pyramid's lod "
           "shift towards the corners with its sign turned fails every path of its kernel, and the ring's reads at the "
           "complement of their angle every path of the ring's.\n"
           "- **DownsampleCube** (max 8e-6, RMS 4e-7, against both): the GPU is the float reference bit for bit (the "
           "same four additions and one multiplication); against the double means it is 3.8e-6 off at most (2 ULPs "
           "at radiance ~40), RMS 1.8e-7. The bound against float is the double one, so that a path that added in "
           "another order would still pass. Reading a wrong texel moves the means by up to 10 (RMS 0.36).\n"
           "- **ShProject** (max 1.6e-4, RMS 1.1e-4 against float and 1e-4 against double): llvmpipe's atan2 is off "
           "glibc's by up to 2.9e-6 rad, and CubeTexelSolidAngle subtracts four of them, so a texel's solid angle is "
           "off by up to 2.6e-4 relative (measured on a 16² face); over the 1536 texels the values (up to 4π, the solid "
           "angle) end 7.7e-5 from either reference, RMS 5e-5 — every coefficient carries it, hence an RMS near the max. The "
           "float reference, with the shader's tree reduction, is 1.3e-6 from the double one.\n"
           "- **IrradianceCube** (max 1e-5, RMS 1e-6, against both): the host sums the moments in double, so only the "
           "kernel's float sum over 1536 of them is left; measured 4.2e-6, RMS 4.7e-7, against the double, and "
           "7.2e-7 against the float reference (OpenGL's).\n"
           "- **ClusterCube** (max 2.4e-4, RMS 8e-6, against both): the pyramid's sums of radiance, directions and "
           "solid angles; CubeTexelSolidAngle's atan2s carry llvmpipe's last bits (see ShProject) into every sum, "
           "measured 1.2e-4, RMS 3.9e-6, on values up to ~10 (the test sun's energy). The float reference is 2.3e-6 "
           "from the double one.\n"
           "- **PrefilterConvolution** (max 1.4e-5, RMS 1.1e-6 against float and 1.5e-6 against double): the GPU walks "
           "the same tree over the float reference's pyramid (uploaded, so that the row measures the convolution "
           "alone) and lands 6.7e-6 from float, 7.2e-6 from double, RMS 4.6e-7 and 6.9e-7 (5.5e-7 on OpenGL), on "
           "values up to ~9.\n"
           "- **PrefilterConvolution on path b** was a known divergence: its -O form returned wrong values on "
           "lavapipe (Mesa 22.3; largest error 3.4–3.7, RMS 0.4, on values up to ~9) while the walk climbed the tree "
           "in a loop of its own inside the walk's (SPIRV-Tools 2023.1's performance passes made SPIR-V that llvmpipe "
           "executed wrong; SPIRV-Cross's HLSL of it, compiled again without -O, was right). The walk climbs without a "
           "loop now, and the -O form lands where the other paths do; the entry is gone. The rows of "
           "\"PrefilterConvolutionCS, SOURCE_TEXELS_IN_PYRAMID\" are the walk bakes run up to 512², over a pyramid "
           "that holds the source's texels (the reference's own level 0), to the same bounds.\n"
           "- **Preview** (max 1e-6, RMS 1e-7): no C++ reference — sampling a cube with trilinear, seamless filtering "
           "(and llvmpipe's choice at cube corners, which every texel of the 1x1 and 2x2 mips touches) is the texture "
           "unit's business, and a reference of it would measure the reference — so paths b, c, e and d are compared "
           "with path a. All four are bit-identical to it on lavapipe; the bound, a few float32 ULPs of a value in "
           "[0, 1] and far below the 8-bit step the preview is stored at (3.9e-3), leaves room for a compiler that "
           "reorders. It proves that the forms agree, not that PreviewCS is right.\n"
           "- **PbrProbe** (max 1.4e-6 against float and 1.1e-6 against double; RMS 1.5e-7 and 1.6e-7): PBR.fxh's "
           "functions one by one on a regular grid of arguments (roughness 0.25 to 1, cosines 0.1 to 0.9), values "
           "from 0 to about 80 (D). The largest errors are D's, a few ULPs of its largest values, and llvmpipe's sin "
           "and cos in the GGX sample; the singular points are iblkit stress's (docs/stability.md).\n"
           "- **LutProbe** (max 1.2e-6 against float and 2.4e-6 against double; RMS 2.4e-7 and 6e-7): the "
           "quadrature LUT's function at the same grid: the quadrature LUT's own bounds, at arguments that are not "
           "texel centres.\n"
           "- **BsdfProbe** (max 5.3e-6 against float and 3.8e-6 against double; RMS 2.2e-7 and 1.9e-7): the path "
           "tracer's functions (document/Common/Bsdf.fxh, Sampling.fxh, Lights.fxh) at 36 arguments: N·L 0.15 to "
           "0.95, N·V 0.3 and 0.8, roughness 0.2 to 1, metalness 0 to 1, values up to 1; measured 2.6e-6 and 1.9e-6 "
           "(OpenGL), RMS 1.1e-7 and 9.3e-8 — llvmpipe's sin, cos and sqrt in the directions and samples, a few tens "
           "of float ULPs. The generator's draws are integers and match exactly. The densities are taken at the "
           "host's cosines: at a sampled half vector near its peak the GGX density is ill-conditioned in float "
           "(1e-4 relative, the float reference as much as the GPU). k for IBL, an inverted η or Walter's half vector "
           "of the wrong sign moves values by 1e-2 and more.\n"
           "- **RenderReference** (max 9.4, RMS 9.4e-2): no C++ reference (a C++ path tracer would be a second "
           "renderer to prove), so the paths are compared with path a: 16 paths a pixel over the 13×5 grid of 8-pixel "
           "spheres, lit by the environment, a directional, a point and an area light; the sums of radiance and of "
           "its square, up to a few thousand. The Vulkan forms are bit-identical to path a; OpenGL's llvmpipe "
           "rounds sin, cos and sqrt in the sampled directions otherwise, and the paths carry it into the sums. The "
           "environment is read bilinearly, so every rounding of a direction moves the radiance it reads by the "
           "environment's gradient there (read texel by texel, only a rounding across a texel's edge did: 0.26, "
           "3.3e3 ULPs, on the 7×4 grid), and the near-mirror spheres of roughness 0.02 to 0.15 follow a direction "
           "most closely: measured 4.68, RMS 4.7e-2, 1.2e4 ULPs (about 1e-3 relative). Both materials (the document's "
           "BSDF and the split sum's) alike. It proves that the forms agree, not that the renderer is right: "
           "tests/render/render_gpu_test.cpp does that.\n"
           "- **SplitSumSpheres** (max 2e-5, RMS 4.6e-7): the kit's recipe on the same grid (the lobe table's "
           "direction and pair of lookups, a disk light from mip 2 on) and the glass's refraction, against path a; "
           "the Vulkan forms are bit-identical, OpenGL's texture filtering 7.6e-6 off (30 ULPs), RMS 2.1e-7.\n"
           "- **ForwardSpheres** (max 0.21, RMS 1.3e-2): the same spheres drawn as an engine draws them, a 96 × 48 "
           "unit-sphere mesh instanced per cell, each pixel shaded from the mesh's interpolated normal, against "
           "SplitSumSpheresCS's exact normal on path a, where both cover the pixel. The difference is the mesh's: "
           "measured 0.101, RMS 6.3e-3 on every path (0.267 and 1.8e-2 at 48 × 24, 0.035 and 1.7e-3 at 192 × 96), "
           "largest at the silhouette, where the shading turns fastest; the three paths (the SPIR-V, the HLSL form, "
           "OpenGL) agree with one another to 10 ULPs.\n";
}

} // namespace iblkit::consistency
