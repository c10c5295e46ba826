// A level's medals (tire/io/level_medals.h, levels/README.md "medals"): read with precise errors,
// and earned by the tick a win comes at.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "error_messages.h"
#include "tire/io/level.h"
#include "tire/io/level_medals.h"

using namespace tire;
using json = nlohmann::json;
using tire_test::has;
using tire_test::joined;

namespace {

json level_with(const json& medals, const json& time_limit = 40) {
  json doc{{"name", "m"}, {"tires", {{{"position", {0, 0.5}}}}}, {"medals", medals}};
  if (!time_limit.is_null()) doc["time_limit"] = time_limit;
  return doc;
}

std::vector<std::string> errors_of(const json& doc) { return load_level_text(doc.dump(), "m.json").errors; }

}  // namespace

TEST_CASE("medals: a win within a medal's time earns it, counted in ticks as a time limit is",
          "[unit][medals]") {
  const LevelMedals m{10.0, 20.0, 30.0};
  const double dt = 1.0 / 60.0;
  CHECK(medal_for(m, 1, dt) == Medal::gold);
  CHECK(medal_for(m, 600, dt) == Medal::gold);  // exactly 10 s
  CHECK(medal_for(m, 601, dt) == Medal::silver);
  CHECK(medal_for(m, 1200, dt) == Medal::silver);
  CHECK(medal_for(m, 1201, dt) == Medal::bronze);
  CHECK(medal_for(m, 1800, dt) == Medal::bronze);
  CHECK(medal_for(m, 1801, dt) == Medal::none);
  // The levels' tick, 0.0166667 s: 9.85 s is tick 591, whose time is 9.8500197 s.
  CHECK(medal_for({9.85, 12.0, 15.0}, 591, 0.0166667) == Medal::gold);
  CHECK(medal_for({9.85, 12.0, 15.0}, 592, 0.0166667) == Medal::silver);

  CHECK(next_medal(Medal::none) == Medal::bronze);
  CHECK(next_medal(Medal::bronze) == Medal::silver);
  CHECK(next_medal(Medal::silver) == Medal::gold);
  CHECK(next_medal(Medal::gold) == Medal::none);
  CHECK(medal_time(m, Medal::silver) == 20.0);
  CHECK_FALSE(medal_time(m, Medal::none));
  for (const Medal x : {Medal::none, Medal::bronze, Medal::silver, Medal::gold})
    CHECK(medal_from_name(medal_name(x)) == x);
  CHECK_FALSE(medal_from_name("platinum"));
}

TEST_CASE("medals: a level's medals are read, and each mistake named with its path", "[unit][medals]") {
  const LevelLoad ok =
      load_level_text(level_with({{"gold", 12}, {"silver", 16}, {"bronze", 25}}).dump(), "m.json");
  INFO(joined(ok.errors));
  REQUIRE(ok.level);
  REQUIRE(ok.level->medals);
  CHECK(ok.level->medals->gold == 12.0);
  CHECK(ok.level->medals->silver == 16.0);
  CHECK(ok.level->medals->bronze == 25.0);
  // Without a time limit, any bronze time in range.
  CHECK(load_level_text(level_with({{"gold", 1}, {"silver", 2}, {"bronze", 900}}, nullptr).dump(), "m.json")
            .level);
  const LevelLoad none = load_level_text(json{{"name", "m"}}.dump(), "m.json");
  REQUIRE(none.level);
  CHECK_FALSE(none.level->medals);

  const std::pair<json, const char*> cases[] = {
      {level_with({{"gold", 12}, {"bronze", 25}}),
       "m.json: /medals/silver: is required: a number in (0, 86400] s"},
      {level_with({{"gold", 16}, {"silver", 16}, {"bronze", 25}}),
       "m.json: /medals/gold: must be less than silver (16), got 16"},
      {level_with({{"gold", 12}, {"silver", 30}, {"bronze", 25}}),
       "m.json: /medals/silver: must be less than bronze (25), got 30"},
      {level_with({{"gold", 12}, {"silver", 16}, {"bronze", 45}}),
       "m.json: /medals/bronze: must be at most the time limit (40 s), got 45"},
      {level_with({{"gold", 0}, {"silver", 16}, {"bronze", 25}}),
       "m.json: /medals/gold: must be a number in (0, 86400]"},
      {level_with({{"gold", 12}, {"silver", 16}, {"bronze", 25}, {"platinum", 5}}),
       "m.json: /medals/platinum"},
      {level_with(json::array({12, 16, 25})), "m.json: /medals: must be an object"},
  };
  for (const auto& [doc, expected] : cases) {
    const auto errors = errors_of(doc);
    INFO(doc.dump() << "\n" << joined(errors));
    CHECK(has(errors, expected));
  }
}
