// SHA-256 digests (OpenSSL's libcrypto): the names and checksums of the native-code cache.
#pragma once

#include <string>
#include <string_view>

namespace unidyn {

// SHA-256 of bytes, as 64 lower-case hexadecimal digits.
std::string sha256_hex(std::string_view bytes);

// SHA-256 of everything that can be read from an open file descriptor from its current offset
// on, and how many bytes that was. Throws std::runtime_error when reading fails.
struct FileDigest {
  std::string sha256;
  unsigned long long size = 0;
};
FileDigest sha256_of_descriptor(int fd);

}  // namespace unidyn
