#include "level_document.h"

#include <algorithm>

#include "level_format.h"
#include "tire/io/file_io.h"

namespace editor {

std::string LevelDocument::open(const std::filesystem::path& file) {
  file_ = file;
  Json doc = Json::object();
  std::error_code ec;
  if (std::filesystem::exists(file, ec)) {
    std::string error;
    const auto text = tire::read_level_text(file, error);
    if (!text) return file.string() + ": " + error;
    // The loader's bounded parse judges the text first (size, depth, syntax with line and column);
    // the editor then keeps its own ordered copy, so that keys stay in the author's order.
    const tire::LevelOpen load = tire::open_level_text(*text, file.string());
    doc = Json::parse(*text, nullptr, false);
    if (doc.is_discarded()) return load.errors.empty() ? file.string() + ": not JSON" : load.errors.front();
    if (!doc.is_object()) return file.string() + ": a level is a JSON object";
  } else {
    doc = new_level(file);
  }
  saved_ = std::filesystem::exists(file, ec) ? doc : Json::object();
  undo_.clear();
  redo_.clear();
  in_gesture_ = false;
  Judgement j = judge(doc);
  set(std::move(doc), std::move(j));
  return "";
}

LevelDocument::Judgement LevelDocument::judge(const Json& doc) const {
  // Judged by the loader itself, from the text the document would be saved as: the messages are
  // tirectl validate's, and nothing is judged twice in two ways.
  tire::LevelOpen load = tire::open_level_text(doc.dump(), file_.string());
  return {std::move(load.errors), std::move(load.level), std::move(load.info)};
}

namespace {

// The first of `next` that `base` does not hold, or "".
std::string first_new(const std::vector<std::string>& next, const std::vector<std::string>& base) {
  for (const std::string& e : next)
    if (std::find(base.begin(), base.end(), e) == base.end()) return e;
  return "";
}

}  // namespace

void LevelDocument::set(Json doc, Judgement judgement) {
  doc_ = std::move(doc);
  errors_ = std::move(judgement.errors);
  level_ = std::move(judgement.level);
  info_ = std::move(judgement.info);
  ++version_;
}

std::string LevelDocument::change(Json next) {
  if (in_gesture_) cancel_gesture();
  if (next == doc_) return "";
  Judgement j = judge(next);
  if (std::string e = first_new(j.errors, errors_); !e.empty()) return e;
  undo_.push_back(doc_);
  redo_.clear();
  set(std::move(next), std::move(j));
  return "";
}

void LevelDocument::begin_gesture() {
  if (in_gesture_) return;
  in_gesture_ = true;
  gesture_start_ = doc_;
}

void LevelDocument::preview(Json next) {
  if (!in_gesture_) begin_gesture();
  Judgement j = judge(next);
  set(std::move(next), std::move(j));
}

std::string LevelDocument::end_gesture() {
  if (!in_gesture_) return "";
  in_gesture_ = false;
  if (doc_ == gesture_start_) return "";
  // Judged against the document the gesture began with.
  Judgement before = judge(gesture_start_);
  if (const std::string e = first_new(errors_, before.errors); !e.empty()) {
    set(std::move(gesture_start_), std::move(before));
    return e;
  }
  undo_.push_back(std::move(gesture_start_));
  redo_.clear();
  return "";
}

void LevelDocument::cancel_gesture() {
  if (!in_gesture_) return;
  in_gesture_ = false;
  Judgement j = judge(gesture_start_);
  set(std::move(gesture_start_), std::move(j));
}

bool LevelDocument::travel(std::vector<Json>& from, std::vector<Json>& to) {
  if (in_gesture_) cancel_gesture();
  if (from.empty()) return false;
  to.push_back(doc_);
  Json doc = std::move(from.back());
  from.pop_back();
  Judgement j = judge(doc);
  set(std::move(doc), std::move(j));
  return true;
}

bool LevelDocument::undo() { return travel(undo_, redo_); }

bool LevelDocument::redo() { return travel(redo_, undo_); }

std::string LevelDocument::save() {
  if (in_gesture_) return "finish the drag first";
  if (!errors_.empty()) return "not saved: " + errors_.front();
  std::string error;
  if (!tire::write_file_atomically(file_, level_text(doc_), error)) return "not saved: " + error;
  saved_ = doc_;
  return "";
}

}  // namespace editor
