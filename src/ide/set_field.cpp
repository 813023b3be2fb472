// Setting one field of one node, checked by the field's description; a node's template mark
// and its user data.

#include "gdpn/ide/set_field.h"

#include <functional>

#include "gdpn/core/text.h"
#include "gdpn/ide/document.h"

namespace gdpn::ide {

SetFieldCommand::SetFieldCommand(std::string path, std::string field, scene::FieldValue value, std::uint64_t drag)
    : path_(std::move(path)), field_(std::move(field)), value_(std::move(value)), drag_(drag) {}

std::string SetFieldCommand::apply(Document& doc) {
  auto* scene = doc.scene();
  auto* node = scene ? scene->find(path_) : nullptr;
  if (node == nullptr) return "no node '" + path_ + "'";
  const int i = node->type().fieldIndex(field_);
  if (i < 0) return "a " + node->type().name + " has no field '" + field_ + "'";
  const auto& desc = *node->type().fields[static_cast<std::size_t>(i)];
  if (auto bad = desc.check(value_)) return bad->message;
  old_ = node->value(static_cast<std::size_t>(i));
  node->setValue(static_cast<std::size_t>(i), value_);
  // a value set by hand no longer comes from the parameter the field named
  old_params_ = node->params;
  std::erase_if(node->params, [i](const auto& p) { return p.field == static_cast<std::uint32_t>(i); });
  return {};
}

void SetFieldCommand::revert(Document& doc) {
  auto* node = doc.scene()->find(path_);
  node->setValue(static_cast<std::size_t>(node->type().fieldIndex(field_)), old_);
  node->params = old_params_;
}

std::string SetFieldCommand::label() const { return "set " + path_ + "." + field_; }

std::uint64_t SetFieldCommand::mergeKey() const {
  if (drag_ == 0) return 0;
  const auto h = std::hash<std::string>{}(path_ + '\n' + field_);
  return (h ^ (drag_ * 0x9E3779B97F4A7C15ULL)) | 1U;
}

void SetFieldCommand::absorb(const Command& next) {
  // the step keeps its first old value and takes the latest new one
  value_ = static_cast<const SetFieldCommand&>(next).value_;
}

std::string SetTemplateCommand::apply(Document& doc) {
  auto* scene = doc.scene();
  auto* node = scene ? scene->find(path_) : nullptr;
  if (node == nullptr) return "no node '" + path_ + "'";
  if (node->parent() == nullptr) return "the scene's root is no template";
  old_ = node->is_template;
  node->is_template = on_;
  return {};
}

void SetTemplateCommand::revert(Document& doc) { doc.scene()->find(path_)->is_template = old_; }

std::string SetTemplateCommand::label() const { return (on_ ? "make a template of " : "unmark template ") + path_; }

std::string SetDatumCommand::apply(Document& doc) {
  auto* scene = doc.scene();
  auto* node = scene ? scene->find(path_) : nullptr;
  if (node == nullptr) return "no node '" + path_ + "'";
  if (!core::isIdentifier(key_)) return "datum name '" + key_ + "' is not an identifier (letters, digits and '_')";
  if (value_ && !scene::isDatumKind(*value_)) return "datum '" + key_ + "' is a bool, a number, text or a list of numbers";
  if (!value_ && node->datum(key_) == nullptr) return "node '" + path_ + "' has no datum '" + key_ + "'";
  old_ = node->data;
  if (value_) node->setDatum(key_, *value_);
  else node->eraseDatum(key_);
  return {};
}

void SetDatumCommand::revert(Document& doc) { doc.scene()->find(path_)->data = old_; }

std::string SetDatumCommand::label() const { return (value_ ? "set " : "remove ") + path_ + ".data." + key_; }

}  // namespace gdpn::ide

namespace gdpn::ide {

namespace {

bool toNumber(const std::string& word, double& x) {
  try {
    std::size_t used = 0;
    x = std::stod(word, &used);
    return used == word.size();
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

std::optional<scene::FieldValue> fieldValueFromWords(const scene::FieldDesc& desc, const std::vector<std::string>& words,
                                                     bool list, std::string& why) {
  using K = scene::FieldKind;
  const auto numbers = [&](std::size_t n, std::vector<double>& out) {
    if (n != 0 && words.size() != n) {
      why = "'" + desc.name + "' expects " + std::to_string(n) + " numbers";
      return false;
    }
    for (const auto& w : words) {
      double x = 0;
      if (!toNumber(w, x)) {
        why = "'" + desc.name + "' expects numbers, got \"" + w + "\"";
        return false;
      }
      out.push_back(x);
    }
    return true;
  };
  std::vector<double> xs;
  switch (desc.kind) {
    case K::Bool:
      if (!list && words.size() == 1 && (words[0] == "true" || words[0] == "false")) return words[0] == "true";
      why = "'" + desc.name + "' expects true or false";
      return std::nullopt;
    case K::Int:
    case K::Float:
      if (list || !numbers(1, xs)) {
        if (why.empty()) why = "'" + desc.name + "' expects a number";
        return std::nullopt;
      }
      if (desc.kind == K::Int) {
        if (xs[0] != static_cast<double>(static_cast<std::int64_t>(xs[0]))) {
          why = "'" + desc.name + "' expects a whole number";
          return std::nullopt;
        }
        return static_cast<std::int64_t>(xs[0]);
      }
      return xs[0];
    case K::Vec3:
    case K::Color:
      if (!numbers(3, xs)) return std::nullopt;
      return std::array<double, 3>{xs[0], xs[1], xs[2]};
    case K::Rotation:
      if (!numbers(4, xs)) return std::nullopt;
      return std::array<double, 4>{xs[0], xs[1], xs[2], xs[3]};
    case K::FloatList:
      if (!numbers(0, xs)) return std::nullopt;
      return xs;
    case K::Enum:
    case K::String:
    case K::File:
      if (list || words.size() != 1) {
        why = "'" + desc.name + "' expects a word";
        return std::nullopt;
      }
      return words[0];
  }
  why = "unknown field kind";
  return std::nullopt;
}

}  // namespace gdpn::ide
