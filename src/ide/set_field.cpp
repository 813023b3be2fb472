// Setting one field of one node, checked by the field's description.

#include "gdpn/ide/set_field.h"

#include <functional>

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
  return {};
}

void SetFieldCommand::revert(Document& doc) {
  auto* node = doc.scene()->find(path_);
  node->setValue(static_cast<std::size_t>(node->type().fieldIndex(field_)), old_);
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

}  // namespace gdpn::ide
