#pragma once
/// \file
/// Commands that set what one scene node holds: a field, checked by the field's own
/// description (the check the model loader uses); its template mark; a datum of its user data.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/ide/command.h"
#include "gdpn/scene/node.h"
#include "gdpn/scene/types.h"
#include "gdpn/scene/user_data.h"

namespace gdpn::ide {

/// Sets field `field` of the node at `path` to `value`.
class SetFieldCommand final : public Command {
 public:
  /// `drag`: the id of the drag this edit belongs to (edits of one drag of one field merge into
  /// one step); 0 for a single edit.
  SetFieldCommand(std::string path, std::string field, scene::FieldValue value, std::uint64_t drag = 0);
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  [[nodiscard]] std::uint64_t mergeKey() const override;
  void absorb(const Command& next) override;

 private:
  std::string path_;   // the node
  std::string field_;  // the field's name
  scene::FieldValue value_, old_;
  std::vector<scene::Node::Binding> old_params_;  // the node's parameter bindings before
  std::uint64_t drag_;
};

/// Marks the node at `path` as a template, or not (Node::is_template).
class SetTemplateCommand final : public Command {
 public:
  SetTemplateCommand(std::string path, bool on) : path_(std::move(path)), on_(on) {}
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  void absorb(const Command&) override {}

 private:
  std::string path_;
  bool on_, old_ = false;
};

/// Sets datum `key` of the user data of the node at `path` to `value`; removes it when
/// `value` is empty.
class SetDatumCommand final : public Command {
 public:
  SetDatumCommand(std::string path, std::string key, std::optional<scene::FieldValue> value)
      : path_(std::move(path)), key_(std::move(key)), value_(std::move(value)) {}
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  void absorb(const Command&) override {}

 private:
  std::string path_, key_;
  std::optional<scene::FieldValue> value_;
  scene::UserData old_;  // the data before, restored whole (order included)
};

/// The value of field `desc` written as `words` (one word for a scalar, one a number for a
/// vector or list; `list` when written as a list), or nullopt with `why`. The range and the
/// other checks are the command's (FieldDesc::check).
std::optional<scene::FieldValue> fieldValueFromWords(const scene::FieldDesc& desc, const std::vector<std::string>& words,
                                                     bool list, std::string& why);

}  // namespace gdpn::ide
