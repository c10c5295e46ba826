// The engine's side of replays (tire/replay/replay_file.h holds the format and what programs use):
// reading one from parsed JSON, what reading cost, and playing inputs into a level session.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tire/io/json_reader.h"
#include "tire/io/level.h"
#include "tire/replay/replay_file.h"
#include "tire/session/level_session.h"

namespace tire {

std::optional<Replay> read_replay(const nlohmann::json& doc, std::vector<JsonIssue>& issues);

// load_replay_text, and what reading it cost (the parser's work), counted into `work`.
ReplayLoad load_replay_text(const std::string& text, const std::string& file, JsonWork& work);

// Plays one input into a level session. `held` is the tick's player input: its steer and inflate
// carry over between ticks, its jump is for this tick only (the caller clears it after the step).
// A restart rebuilds the session from `level`.
void apply_input(const ReplayInput& input, LevelSession& session, const Level& level, TickInput& held);

// Applies the feed's inputs for the next tick to `session` and steps it.
void step(InputFeed& feed, LevelSession& session, const Level& level);

}  // namespace tire
