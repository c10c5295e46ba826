// The level being edited: its JSON as its author reads it (keys in their order, scripts as they
// were), every change as one step of an unbounded undo history, and what the validator says of it.
// A change the validator refuses is not made; the validator's message says why. Nothing here knows
// about SDL: the editor's window drives it, and the tests drive it directly.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "level_items.h"
#include "tire/level.h"

namespace editor {

class LevelDocument {
 public:
  // Opens `file`; when it does not exist, starts a new level named after it (not written until
  // saved). Returns "" or why it cannot be opened (unreadable, not JSON, past the size limits). A
  // level the validator refuses opens, so that it can be fixed; errors() lists what is wrong.
  std::string open(const std::filesystem::path& file);

  const std::filesystem::path& file() const { return file_; }
  const Json& json() const { return doc_; }

  // Makes `next` the document, as one step of the history. Refused, returning the validator's
  // first new message, when it adds errors; "" when made.
  std::string change(Json next);

  // A gesture (a drag) shows its changes as it goes and becomes one step when it ends: preview()
  // replaces the document without judging it, end_gesture() then judges the result as change()
  // does and puts back the document the gesture began with when it is refused.
  void begin_gesture();
  void preview(Json next);
  std::string end_gesture();
  void cancel_gesture();
  bool in_gesture() const { return in_gesture_; }

  bool undo();
  bool redo();
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  std::size_t history_size() const { return undo_.size(); }

  // The document differs from the file as last opened or saved.
  bool modified() const { return doc_ != saved_; }
  // The validator's messages for the document as it is ("FILE: /json/path: ..."), as tirectl
  // validate prints them.
  const std::vector<std::string>& errors() const { return errors_; }
  // The document as a level, or null while it does not validate.
  const std::shared_ptr<const tire::Level>& level() const { return level_; }
  // What it shows (name, bounds, ...) while it validates; empty otherwise.
  const tire::LevelInfo& info() const { return info_; }
  // Goes up with every change of the document, previews included.
  std::uint64_t version() const { return version_; }

  // Writes the document as the level file (level_format.h), atomically, if it validates. Returns
  // "" or why not.
  std::string save();

 private:
  struct Judgement {
    std::vector<std::string> errors;
    std::shared_ptr<const tire::Level> level;
    tire::LevelInfo info;
  };
  Judgement judge(const Json& doc) const;
  void set(Json doc, Judgement judgement);
  // Undo (from the undo stack to the redo stack) or redo (the other way).
  bool travel(std::vector<Json>& from, std::vector<Json>& to);

  std::filesystem::path file_;
  Json doc_ = Json::object();
  Json saved_ = Json::object();
  std::vector<std::string> errors_;
  std::shared_ptr<const tire::Level> level_;
  tire::LevelInfo info_;
  std::uint64_t version_ = 0;
  std::vector<Json> undo_, redo_;
  bool in_gesture_ = false;
  Json gesture_start_;
};

}  // namespace editor
