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
