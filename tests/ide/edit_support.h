#pragma once
// Test support for the edit-command tests: the factory opened as a document, a saved text read
// back, and the property every edit sequence must have (undo all: the start; redo all: the end).

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "gdpn/ide/document.h"
#include "gdpn/model/model.h"

namespace gdpn::ide::testing {

/// examples/factory as a document.
inline std::unique_ptr<Document> openFactory() {
  core::Diagnostics diags;
  auto doc = Document::open(std::string(GDPN_SOURCE_DIR) + "/examples/factory/factory.gdpn.yaml", diags);
  EXPECT_TRUE(doc) << diags.str();
  return doc;
}

/// The text parses back into a model with no error.
inline void readsBack(const std::string& text) {
  core::Diagnostics diags;
  EXPECT_TRUE(model::parseModel(text, "edited.gdpn.yaml", diags)) << diags.str();
  EXPECT_FALSE(diags.hasErrors()) << diags.str();
}

/// Undoes every step: the save is `start` again, byte for byte; redoes them all: it is the
/// save the sequence ended with.
inline void undoesToStartAndRedoesToEnd(Document& doc, const std::string& start, const std::string& why) {
  const auto end = doc.text();
  readsBack(end);
  while (doc.undo()) {
  }
  EXPECT_EQ(doc.text(), start) << why;
  while (doc.redo()) {
  }
  EXPECT_EQ(doc.text(), end) << why;
}

}  // namespace gdpn::ide::testing
