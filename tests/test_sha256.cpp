// The engine's own SHA-256 (engine/io/sha256.cpp, used where there is no OpenSSL, as in the
// browser) against the published test vectors and against OpenSSL's on the shipped levels and on
// every length around the padding's block boundaries.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "sha256.h"
#include "tire/io/file_io.h"

namespace {

std::string hex(const std::array<std::uint8_t, 32>& d) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  for (const std::uint8_t b : d) {
    out += digits[b >> 4];
    out += digits[b & 0xf];
  }
  return out;
}

}  // namespace

TEST_CASE("the engine's own SHA-256 gives the FIPS 180-4 test vectors", "[sha256]") {
  using tire::detail::sha256_portable;
  CHECK(hex(sha256_portable("")) == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(hex(sha256_portable("abc")) == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(hex(sha256_portable("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq")) ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(hex(sha256_portable(std::string(1000000, 'a'))) ==
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("the engine's own SHA-256 agrees with OpenSSL's on every length up to 300 bytes and on the levels",
          "[sha256]") {
  std::string bytes;
  for (int n = 0; n <= 300; ++n) {
    INFO("length " << n);
    CHECK(hex(tire::detail::sha256_portable(bytes)) == tire::sha256_hex(bytes));
    bytes += static_cast<char>((n * 131 + 7) & 0xff);
  }
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(TIRE_SOURCE_DIR) / "levels")) {
    if (entry.path().extension() != ".json") continue;
    std::string error;
    const auto text = tire::read_file(entry.path(), 1 << 24, error);
    REQUIRE(text);
    INFO(entry.path().string());
    CHECK(hex(tire::detail::sha256_portable(*text)) == tire::sha256_hex(*text));
  }
}
