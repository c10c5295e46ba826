// A small, deterministic mutator for running a fuzz target without libFuzzer (session_main.cpp): new
// inputs from a corpus by byte flips, dictionary splices, numeric tweaks, duplicated JSON objects
// and pieces of other inputs. What it makes depends only on its seed and the number of calls, never
// on time, so a test run is the same every time and a failure is found again by running it again.
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tire::fuzz {

// Reads a libFuzzer dictionary (lines `"token"` or `name="token"`, escapes \\ \" \xAB; # comments).
// Returns nullopt, with the line in `error`, for a line it cannot read.
inline std::optional<std::vector<std::string>> read_dictionary(const std::string& file, std::string& error) {
  std::ifstream in(file);
  if (!in) {
    error = file + ": cannot read";
    return std::nullopt;
  }
  std::vector<std::string> words;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::size_t open = line.find('"'), close = line.rfind('"');
    if (open == std::string::npos || close <= open) {
      error = file + ":" + std::to_string(number) + ": expected \"token\"";
      return std::nullopt;
    }
    std::string word;
    for (std::size_t i = open + 1; i < close; ++i) {
      if (line[i] != '\\' || i + 1 >= close) {
        word += line[i];
      } else if (line[i + 1] == 'x' && i + 3 < close) {
        word += static_cast<char>(std::stoi(line.substr(i + 2, 2), nullptr, 16));
        i += 3;
      } else {
        word += line[++i];
      }
    }
    words.push_back(word);
  }
  return words;
}

class Mutator {
 public:
  static constexpr std::size_t kMaxSize = 65536;  // as tools/fuzz's -max_len

  Mutator(std::uint64_t seed, std::vector<std::string> dictionary)
      : state_(seed), dictionary_(std::move(dictionary)) {}

  // A new input: an entry of `corpus` (not empty) changed by one edit, sometimes two to four.
  std::string mutate(const std::vector<std::string>& corpus) {
    std::string s = corpus[below(corpus.size())];
    const std::size_t edits = below(4) == 0 ? 2 + below(3) : 1;
    for (std::size_t e = 0; e < edits; ++e) edit(s, corpus);
    if (s.size() > kMaxSize) s.resize(kMaxSize);
    return s;
  }

 private:
  // splitmix64 (Steele, Lea & Flood 2014).
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }

  // Mostly edits that keep a level's JSON well formed (numbers, whole strings, whole objects), so
  // that most inputs get past the parser and play; raw byte edits for the parser and validator.
  void edit(std::string& s, const std::vector<std::string>& corpus) {
    const std::size_t pick = below(20);
    if (pick < 6) {
      tweak_number(s);
    } else if (pick < 9) {
      duplicate_object(s);
    } else if (pick < 11) {
      erase_object(s);
    } else if (pick < 14) {
      replace_string(s);
    } else if (pick < 15) {
      if (!dictionary_.empty()) s.insert(below(s.size() + 1), dictionary_[below(dictionary_.size())]);
    } else if (pick < 16) {
      const std::string& other = corpus[below(corpus.size())];  // a piece of another input
      if (!other.empty()) s.insert(below(s.size() + 1), other.substr(below(other.size()), 1 + below(512)));
    } else if (s.empty()) {
      return;
    } else if (pick < 17) {
      s[below(s.size())] ^= static_cast<char>(1u << below(8));  // a bit flipped
    } else if (pick < 19) {
      static constexpr char kBytes[] = "0123456789-.e\"{}[],: \\\0\xff";  // bytes JSON cares about
      s[below(s.size())] = kBytes[below(sizeof kBytes - 1)];
    } else {
      s.erase(below(s.size()), 1 + below(16));
    }
  }

  // The extent [open, close] of a JSON object starting at or after `from`, strings skipped.
  std::optional<std::pair<std::size_t, std::size_t>> object_after(const std::string& s, std::size_t from) {
    const std::size_t open = s.find('{', from);
    if (open == std::string::npos) return std::nullopt;
    int depth = 0;
    bool in_string = false;
    for (std::size_t i = open; i < s.size(); ++i) {
      const char c = s[i];
      if (in_string) {
        if (c == '\\')
          ++i;
        else if (c == '"')
          in_string = false;
      } else if (c == '"') {
        in_string = true;
      } else if (c == '{') {
        ++depth;
      } else if (c == '}' && --depth == 0) {
        return std::pair{open, i};
      }
    }
    return std::nullopt;
  }

  // An object copied after itself: one more tire, trigger, action or prop.
  void duplicate_object(std::string& s) {
    const auto o = object_after(s, s.empty() ? 0 : below(s.size()));
    if (!o) return;
    const std::string object = s.substr(o->first, o->second - o->first + 1);
    if (s.size() + object.size() < kMaxSize) s.insert(o->second + 1, ", " + object);
  }

  // An object taken out with the comma after it: one tire, trigger, action or prop fewer.
  void erase_object(std::string& s) {
    const auto o = object_after(s, s.empty() ? 0 : below(s.size()));
    if (!o) return;
    std::size_t end = o->second + 1;
    while (end < s.size() && (s[end] == ' ' || s[end] == '\n')) ++end;
    if (end < s.size() && s[end] == ',') ++end;
    s.erase(o->first, end - o->first);
  }

  void replace_string(std::string& s) {
    if (dictionary_.empty() || s.empty()) return;
    const std::size_t open = s.find('"', below(s.size()));
    if (open == std::string::npos) return;
    const std::size_t close = s.find('"', open + 1);
    if (close == std::string::npos) return;
    s.replace(open, close - open + 1, dictionary_[below(dictionary_.size())]);
  }

  void tweak_number(std::string& s) {
    // The first number at or after a random place.
    std::size_t at = s.empty() ? 0 : below(s.size());
    while (at < s.size() && !std::isdigit(static_cast<unsigned char>(s[at]))) ++at;
    if (at >= s.size()) return;
    std::size_t begin = at;
    while (begin > 0 && (std::isdigit(static_cast<unsigned char>(s[begin - 1])) || s[begin - 1] == '.' ||
                         s[begin - 1] == '-'))
      --begin;
    std::size_t end = at;
    while (end < s.size() && (std::isdigit(static_cast<unsigned char>(s[end])) || s[end] == '.' ||
                              s[end] == 'e' || s[end] == 'E' || s[end] == '-' || s[end] == '+'))
      ++end;
    double value = 0.0;
    std::istringstream(s.substr(begin, end - begin)) >> value;
    static constexpr std::array<double, 12> kValues{0.0,  1.0,   -1.0, 0.001, 1e-9,  6.0,
                                                    16.0, 256.0, 1e4,  1e6,   1e308, -1e308};
    switch (below(6)) {
      case 0: value = kValues[below(kValues.size())]; break;
      case 1: value *= 2.0; break;
      case 2: value /= 2.0; break;
      case 3: value = -value; break;
      case 4: value += 1.0; break;
      default: value = value * 10.0 + 1.0; break;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    s.replace(begin, end - begin, text);
  }

  std::uint64_t state_;
  std::vector<std::string> dictionary_;
};

}  // namespace tire::fuzz
