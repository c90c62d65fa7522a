// Whether the command is built with AddressSanitizer (and so LeakSanitizer):
// UNIDYN_ADDRESS_SANITIZER.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define UNIDYN_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNIDYN_ADDRESS_SANITIZER 1
#endif
#endif
