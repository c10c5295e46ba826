// Full-screen choices, drawn with ImGui: the level select menu (Esc) and the win / lose screens.
// Keys are handled by the app (so they work the same when scripted); the mouse works here too.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/level_list.h"
#include "tire/io/level_medals.h"
#include "tire/script/script_status.h"

struct ImFont;

namespace game {

enum class MenuChoice { none, load, resume, quit };

// The level list with `selected` highlighted and `current` marked, each level with its note from
// `notes` (the best time; may be shorter than `levels`). A click on a level selects it and returns
// load.
MenuChoice draw_level_menu(const std::vector<LevelEntry>& levels, const std::vector<std::string>& notes,
                           std::size_t& selected, std::optional<std::size_t> current,
                           const std::string& levels_dir, ImFont* big);

enum class EndChoice { none, next, retry };

// The end screen's title: "Level complete!" for a win; for a loss, what ended it: "Time's up",
// "Off the edge" (the level's bounds), "You lost" (the script's lose action).
const char* end_title(tire::ScriptStatus status, tire::EndReason reason);

// The title, the level and its time and `note` ("New best time!", "best 9.85 s"), the medal the run
// earned among the level's `medals` (if it has them), with the next-level / retry buttons.
EndChoice draw_end_screen(tire::ScriptStatus status, tire::EndReason reason, const std::string& level,
                          double time, const std::string& note, tire::Medal medal,
                          const std::optional<tire::LevelMedals>& medals, ImFont* big);

// "Gold medal", "Silver medal", "Bronze medal" or "" for none.
std::string medal_title(tire::Medal medal);

}  // namespace game
