// Whether the tests run under AddressSanitizer (tools/test --sanitize): the sweeps over many
// scenes and views then take a sample of them, so that the sanitized suite fits CI's budget.
// The sanitized run looks for memory and undefined-behaviour errors, which the sample's code
// paths exercise; the Release run keeps the full sweeps and their assertions.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitizedBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitizedBuild = true;
#else
constexpr bool kSanitizedBuild = false;
#endif
#else
constexpr bool kSanitizedBuild = false;
#endif

#include <string_view>

// Under the sanitizers the sweeps over every shipped scene leave out the B-spline volume
// with G1 knots: its three builds of 107 k cells took 538 s of the sampled view-culling
// sweep's 590 s under ASan (docs/PERFORMANCE.md), against ctest's 600 s limit. The Release
// run sweeps it; the sanitized run still builds and renders it in
// SimplexSpline3.ShippedVolumeScenesRenderWithoutPinholes. The other tests that sample under
// the sanitizers say so where they do (grep kSanitizedBuild): together they brought the
// sanitized suite from about 1 610 s to the figure in docs/PERFORMANCE.md.
inline bool leftOutOfSanitizedSweeps(std::string_view sceneStem) {
  return kSanitizedBuild && sceneStem == "bspline_volume_g1";
}
