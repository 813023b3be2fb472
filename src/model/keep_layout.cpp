// Saving over a file written by hand: the canonical text of the edited model, merged into the
// original text entry by entry, so that what the edit did not touch keeps its bytes.

#include "keep_layout.h"

#include "yaml.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <string_view>
#include <vector>

namespace gdpn::model::detail {
namespace {

/// A text cut into lines (a line's end is past its '\n').
class Lines {
 public:
  explicit Lines(const std::string& text) : text_(text) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') starts_.push_back(i + 1);
    }
  }
  [[nodiscard]] const std::string& text() const { return text_; }
  [[nodiscard]] std::size_t count() const { return starts_.size(); }
  [[nodiscard]] std::size_t start(std::size_t line) const { return starts_[line]; }
  [[nodiscard]] std::size_t end(std::size_t line) const { return line + 1 < starts_.size() ? starts_[line + 1] : text_.size(); }
  /// The line without its line break.
  [[nodiscard]] std::string_view view(std::size_t line) const {
    std::string_view v(text_.data() + start(line), end(line) - start(line));
    while (!v.empty() && (v.back() == '\n' || v.back() == '\r')) v.remove_suffix(1);
    return v;
  }
  [[nodiscard]] std::size_t lineOf(std::size_t pos) const {
    return static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), pos) - starts_.begin()) - 1;
  }
  [[nodiscard]] std::size_t indent(std::size_t line) const {
    const auto v = view(line);
    std::size_t n = 0;
    while (n < v.size() && v[n] == ' ') ++n;
    return n;
  }
  [[nodiscard]] bool blank(std::size_t line) const {
    return view(line).find_first_not_of(" \t\r") == std::string_view::npos;
  }
  [[nodiscard]] bool comment(std::size_t line) const {
    const auto v = view(line);
    const std::size_t first = v.find_first_not_of(" \t");
    return first != std::string_view::npos && v[first] == '#';
  }
  /// A list item's dash stands at `column` of `line`.
  [[nodiscard]] bool dashAt(std::size_t line, std::size_t column) const {
    const auto v = view(line);
    return column < v.size() && v[column] == '-' && (column + 1 == v.size() || v[column + 1] == ' ');
  }

 private:
  const std::string& text_;
  std::vector<std::size_t> starts_;
};

/// Where one map entry or list item stands in a text.
struct Span {
  std::size_t lead = 0;    // where the comment and blank lines just above it begin
  std::size_t head = 0;    // its key, or its list item's dash
  std::size_t end = 0;     // past its last line
  std::size_t line = 0;    // of the head
  std::size_t column = 0;  // of the head
  bool line_start = true;  // the head is the first thing on its line (else it follows a "- ")
};

/// One entry of a map or item of a list.
struct Item {
  std::string key;  // "" for a list item
  YAML::Node key_node;
  YAML::Node value;
};

std::vector<Item> itemsOf(const YAML::Node& node) {
  std::vector<Item> items;
  if (node.IsMap()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      const YAML::Node k = it->first;
      const YAML::Node v = it->second;
      items.push_back({k.IsScalar() ? k.Scalar() : std::string(), k, v});
    }
  } else if (node.IsSequence()) {
    for (auto it = node.begin(); it != node.end(); ++it) items.push_back({{}, {}, *it});
  }
  return items;
}

bool block(const YAML::Node& node) {
  return (node.IsMap() || node.IsSequence()) && node.size() > 0 && node.Style() == YAML::EmitterStyle::Block;
}

/// Same content: types, scalars (with their quoting) and entries in order.
bool same(const YAML::Node& a, const YAML::Node& b) {
  if (a.Type() != b.Type()) return false;
  switch (a.Type()) {
    case YAML::NodeType::Scalar: return a.Scalar() == b.Scalar() && a.Tag() == b.Tag();
    case YAML::NodeType::Sequence:
    case YAML::NodeType::Map: {
      if (a.size() != b.size()) return false;
      const auto x = itemsOf(a), y = itemsOf(b);
      for (std::size_t i = 0; i < x.size(); ++i) {
        if (a.IsMap() && !same(x[i].key_node, y[i].key_node)) return false;
        if (!same(x[i].value, y[i].value)) return false;
      }
      return true;
    }
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined: return true;
  }
  return false;
}

/// What a list item is, to match it across an edit: a scene node by its type and name, an arc
/// by its ends, anything else by its whole content.
std::string identity(const YAML::Node& item) {
  if (item.IsMap() && item.size() == 1) {
    const auto entry = itemsOf(item).front();
    if (entry.value.IsMap()) {
      for (const auto& e : itemsOf(entry.value)) {
        if (e.key == "name" && e.value.IsScalar()) return "node\x1f" + entry.key + "\x1f" + e.value.Scalar();
      }
    }
  }
  if (item.IsMap()) {
    std::string from, to;
    for (const auto& e : itemsOf(item)) {
      if (e.key == "from" && e.value.IsScalar()) from = e.value.Scalar();
      if (e.key == "to" && e.value.IsScalar()) to = e.value.Scalar();
    }
    if (!from.empty() && !to.empty()) return "arc\x1f" + from + "\x1f" + to;
  }
  return "content\x1f" + YAML::Dump(item);
}

/// Where the dash of the list item whose content begins at (line, column) stands; nullopt when
/// it is not the first thing on that line.
std::optional<std::size_t> dashColumn(const Lines& lines, std::size_t line, std::size_t column) {
  const auto v = lines.view(line);
  if (column > v.size()) return std::nullopt;
  std::size_t i = column;
  while (i > 0 && v[i - 1] == ' ') --i;
  if (i == 0 || v[i - 1] != '-') return std::nullopt;
  const std::size_t dash = i - 1;
  if (v.substr(0, dash).find_first_not_of(' ') != std::string_view::npos) return std::nullopt;
  return dash;
}

/// The span whose head is at (line, column): it runs on over the lines indented deeper (and
/// blank ones), and over lines at its own indentation that hold items of its value's list
/// (`key:` with its `- item`s below at the same column); the trailing blank lines are not its.
Span spanAt(const Lines& lines, std::size_t line, std::size_t column, bool line_start, bool seq_at_column) {
  Span s;
  s.line = line;
  s.column = column;
  s.line_start = line_start;
  s.head = lines.start(line) + column;
  s.lead = lines.start(line);
  std::size_t last = line;
  for (std::size_t l = line + 1; l < lines.count(); ++l) {
    if (lines.blank(l)) continue;
    const std::size_t indent = lines.indent(l);
    if (indent > column || (seq_at_column && indent == column && lines.dashAt(l, indent))) {
      last = l;
      continue;
    }
    break;
  }
  s.end = lines.end(last);
  return s;
}

/// Gives each span the blank and comment lines just above it (not lines of the span before it);
/// the first span of a nested collection only the comment lines at its own indentation, and
/// the first of the file none (the file's opening comments stay).
void giveLeads(const Lines& lines, std::vector<Span>& spans) {
  if (!spans.empty() && spans[0].line_start && spans[0].column > 0) {
    std::size_t l = spans[0].line;
    while (l > 0 && lines.comment(l - 1) && lines.indent(l - 1) == spans[0].column) --l;
    spans[0].lead = lines.start(l);
  }
  for (std::size_t i = 1; i < spans.size(); ++i) {
    if (!spans[i].line_start) continue;
    const std::size_t floor = lines.lineOf(spans[i - 1].end);
    std::size_t l = spans[i].line;
    while (l > floor && (lines.blank(l - 1) || lines.comment(l - 1))) --l;
    spans[i].lead = std::max(lines.start(l), spans[i - 1].end);
  }
}

/// One change to the original text: `text` in place of [begin, end) (an insertion when they
/// are equal).
struct Edit {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::string text;
  std::size_t order = 0;
};

/// Where a trailing comment on the one line of `from`..`to` begins (with the spaces before it),
/// or npos; quoted text is skipped.
std::size_t trailingComment(std::string_view text, std::size_t from, std::size_t to) {
  char quote = 0;
  for (std::size_t i = from; i < to; ++i) {
    const char c = text[i];
    if (quote == '"') {
      if (c == '\\') ++i;
      else if (c == '"') quote = 0;
    } else if (quote == '\'') {
      if (c == '\'' && i + 1 < to && text[i + 1] == '\'') ++i;  // '' is a quote in the text
      else if (c == '\'') quote = 0;
    } else if (c == '"' || c == '\'') {
      if (i == from || text[i - 1] == ' ' || text[i - 1] == '[' || text[i - 1] == '{' || text[i - 1] == ',' ||
          text[i - 1] == ':') {
        quote = c;
      }
    } else if (c == '#' && i > from && (text[i - 1] == ' ' || text[i - 1] == '\t')) {
      std::size_t b = i;
      while (b > from && (text[b - 1] == ' ' || text[b - 1] == '\t')) --b;
      return b;
    }
  }
  return std::string_view::npos;
}

/// Walks the original's tree beside the canonical trees before and after the edit, and
/// collects the edits of the original's text that make it say what `after` says.
class Merger {
 public:
  Merger(const std::string& original, const std::string& after) : o_(original), a_(after) {
    crlf_ = original.find("\r\n") != std::string::npos;
  }

  /// Merges the block map `o` of the original (whose canonical form is `b`, maybe undefined)
  /// towards `a`; false (with no edits left behind) when it cannot.
  bool map(const YAML::Node& o, const YAML::Node& b, const YAML::Node& a) {
    const std::size_t mark = edits_.size();
    if (!mapEdits(o, b, a)) {
      edits_.resize(mark);
      return false;
    }
    return true;
  }

  /// The original text with the edits made; nullopt when they overlap.
  std::optional<std::string> result() {
    std::stable_sort(edits_.begin(), edits_.end(), [](const Edit& x, const Edit& y) {
      if (x.begin != y.begin) return x.begin < y.begin;
      const bool xi = x.begin == x.end, yi = y.begin == y.end;
      if (xi != yi) return xi;  // insertions first
      return x.order < y.order;
    });
    std::string out;
    std::size_t at = 0;
    for (const auto& e : edits_) {
      if (e.begin < at) return std::nullopt;
      out.append(o_.text(), at, e.begin - at);
      out += e.text;
      at = e.end;
    }
    out.append(o_.text(), at, std::string::npos);
    return out;
  }

 private:
  void edit(std::size_t begin, std::size_t end, std::string text) {
    if (crlf_) {
      std::string converted;
      for (char c : text) {
        if (c == '\n') converted += '\r';
        converted += c;
      }
      text = std::move(converted);
    }
    edits_.push_back({begin, end, std::move(text), edits_.size()});
  }

  /// The spans of the entries of the block map `o` in `lines`; nullopt when a key is not where
  /// a block map's key stands.
  static std::optional<std::vector<Span>> mapSpans(const Lines& lines, const YAML::Node& o) {
    std::vector<Span> spans;
    for (const auto& e : itemsOf(o)) {
      const YAML::Mark m = e.key_node.Mark();
      if (!e.key_node.IsScalar() || m.is_null() || m.line < 0 || static_cast<std::size_t>(m.line) >= lines.count()) {
        return std::nullopt;
      }
      const auto line = static_cast<std::size_t>(m.line), column = static_cast<std::size_t>(m.column);
      const bool line_start = lines.indent(line) == column;
      // only a map's first key may follow a list item's dash on its line
      if (!line_start && (!spans.empty() || !dashColumn(lines, line, column))) return std::nullopt;
      if (!spans.empty() && column != spans.front().column) return std::nullopt;
      bool seq_at_column = false;
      if (block(e.value) && e.value.IsSequence()) {
        const YAML::Mark first = e.value[0].Mark();
        if (!first.is_null() && first.line >= 0) {
          const auto dash = dashColumn(lines, static_cast<std::size_t>(first.line), static_cast<std::size_t>(first.column));
          seq_at_column = dash && *dash == column;
        }
      }
      spans.push_back(spanAt(lines, line, column, line_start, seq_at_column));
    }
    giveLeads(lines, spans);
    return spans;
  }

  /// The spans of the items of the block list `o`; nullopt when a dash is not the first thing
  /// on its line.
  static std::optional<std::vector<Span>> listSpans(const Lines& lines, const YAML::Node& o) {
    std::vector<Span> spans;
    for (const auto& e : itemsOf(o)) {
      const YAML::Mark m = e.value.Mark();
      if (m.is_null() || m.line < 0 || static_cast<std::size_t>(m.line) >= lines.count()) return std::nullopt;
      const auto line = static_cast<std::size_t>(m.line);
      const auto dash = dashColumn(lines, line, static_cast<std::size_t>(m.column));
      if (!dash || (!spans.empty() && *dash != spans.front().column)) return std::nullopt;
      spans.push_back(spanAt(lines, line, *dash, true, false));
    }
    giveLeads(lines, spans);
    return spans;
  }

  /// The text of `span` of the canonical text, its lines after the first moved from its column
  /// to `column`; nullopt when a line is indented less than its head.
  std::optional<std::string> moved(const Span& span, std::size_t column) const {
    std::string out;
    for (std::size_t l = span.line; l < a_.count() && a_.start(l) < span.end; ++l) {
      const std::size_t from = l == span.line ? span.head : a_.start(l);
      const std::string_view text(a_.text().data() + from, a_.end(l) - from);
      if (l == span.line || a_.blank(l)) {
        out += l == span.line ? text : std::string_view("\n");
        continue;
      }
      if (a_.indent(l) < span.column) return std::nullopt;
      out.append(column, ' ');
      out += text.substr(span.column);
    }
    if (out.empty() || out.back() != '\n') out += '\n';
    return out;
  }

  /// The canonical text of the entry `key` of the map `a`, at `column`.
  std::optional<std::string> entryText(const YAML::Node& a, const std::string& key, std::size_t column) const {
    const auto spans = mapSpans(a_, a);
    if (!spans) return std::nullopt;
    const auto items = itemsOf(a);
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (items[i].key == key) return moved((*spans)[i], column);
    }
    return std::nullopt;
  }

  /// `span` of the original given the new text `text` (which ends in a line break), keeping
  /// the comment lines above it and, when both stay on one line, its trailing comment.
  void replace(const Span& span, std::string text) {
    const std::size_t line_end = o_.start(span.line) + o_.view(span.line).size();
    const bool one_line = o_.lineOf(span.end == 0 ? 0 : span.end - 1) == span.line;
    if (one_line) {
      // at the end of the new first line (`key:` of a block, or the whole entry)
      const std::size_t c = trailingComment(o_.text(), span.head, line_end);
      if (c != std::string_view::npos) text.insert(text.find('\n'), o_.text().substr(c, line_end - c));
    }
    // the original's last line may have no line break
    if (span.end == o_.text().size() && (o_.text().empty() || o_.text().back() != '\n')) text.pop_back();
    edit(span.head, span.end, std::move(text));
  }

  void insert(std::size_t at, std::string text) {
    if (at == o_.text().size() && !o_.text().empty() && o_.text().back() != '\n') text.insert(0, "\n");
    edit(at, at, std::move(text));
  }

  /// A value of the original that changed: merged inside when it is a block collection, else
  /// written anew. `write` writes the whole entry anew.
  template <class Write>
  bool changed(const YAML::Node& o, const YAML::Node& b, const YAML::Node& a, Write&& write) {
    if (block(o) && o.IsMap() && a.IsMap() && map(o, b.IsMap() ? b : YAML::Node(YAML::NodeType::Map), a)) return true;
    if (block(o) && o.IsSequence() && a.IsSequence() && b.IsSequence() && b.size() == o.size() && list(o, b, a)) {
      return true;
    }
    return write();
  }

  bool mapEdits(const YAML::Node& o, const YAML::Node& b, const YAML::Node& a) {
    if (!block(o) || !o.IsMap() || !a.IsMap()) return false;
    const auto spans = mapSpans(o_, o);
    if (!spans) return false;
    const auto oi = itemsOf(o), ai = itemsOf(a), bi = itemsOf(b);
    std::map<std::string, std::size_t> in_o, in_a, in_b;
    for (std::size_t i = 0; i < oi.size(); ++i) in_o[oi[i].key] = i;
    for (std::size_t i = 0; i < ai.size(); ++i) in_a[ai[i].key] = i;
    for (std::size_t i = 0; i < bi.size(); ++i) in_b[bi[i].key] = i;
    // the keys all three hold keep their order, else the edit reordered what order means
    std::vector<std::size_t> order_b, order_a;
    for (std::size_t i = 0; i < bi.size(); ++i) {
      if (in_o.count(bi[i].key) != 0 && in_a.count(bi[i].key) != 0) order_b.push_back(i);
    }
    for (std::size_t i = 0; i < ai.size(); ++i) {
      if (auto it = in_b.find(ai[i].key); it != in_b.end() && in_o.count(ai[i].key) != 0) order_a.push_back(it->second);
    }
    if (order_a != order_b) return false;
    const std::size_t column = spans->front().column;
    // the original's entries: kept, merged, written anew or removed
    for (std::size_t i = 0; i < oi.size(); ++i) {
      const Span& span = (*spans)[i];
      const auto na = in_a.find(oi[i].key);
      const auto nb = in_b.find(oi[i].key);
      if (na == in_a.end()) {
        if (nb == in_b.end()) continue;  // a default the file spells out
        if (!span.line_start) return false;
        edit(span.lead, span.end, {});
        continue;
      }
      const YAML::Node bv = nb == in_b.end() ? YAML::Node() : bi[nb->second].value;
      const YAML::Node av = ai[na->second].value;
      if (nb != in_b.end() && same(bv, av)) continue;
      const bool done = changed(oi[i].value, bv, av, [&] {
        auto text = entryText(a, oi[i].key, column);
        if (!text) return false;
        replace(span, std::move(*text));
        return true;
      });
      if (!done) return false;
    }
    // new entries follow their canonical predecessor
    std::optional<std::size_t> anchor;
    if (spans->front().line_start) anchor = spans->front().lead;
    for (std::size_t i = 0; i < ai.size(); ++i) {
      if (auto it = in_o.find(ai[i].key); it != in_o.end()) {
        anchor = (*spans)[it->second].end;
        continue;
      }
      if (auto nb = in_b.find(ai[i].key); nb != in_b.end() && same(bi[nb->second].value, ai[i].value)) continue;
      if (!anchor) return false;
      auto text = entryText(a, ai[i].key, column);
      if (!text) return false;
      insert(*anchor, std::string(column, ' ') + *text);
    }
    return true;
  }

  bool list(const YAML::Node& o, const YAML::Node& b, const YAML::Node& a) {
    const std::size_t mark = edits_.size();
    if (!listEdits(o, b, a)) {
      edits_.resize(mark);
      return false;
    }
    return true;
  }

  bool listEdits(const YAML::Node& o, const YAML::Node& b, const YAML::Node& a) {
    const auto spans = listSpans(o_, o);
    const auto a_spans = listSpans(a_, a);
    if (!spans || !a_spans || b.size() != spans->size()) return false;
    const auto bi = itemsOf(b), ai = itemsOf(a), oi = itemsOf(o);
    std::vector<std::string> ib, ia;
    for (const auto& x : bi) ib.push_back(identity(x.value));
    for (const auto& x : ai) ia.push_back(identity(x.value));
    // match items: the common ends, then the longest common subsequence of what is between
    std::size_t head = 0;
    while (head < ib.size() && head < ia.size() && ib[head] == ia[head]) ++head;
    std::size_t tail = 0;
    while (tail < ib.size() - head && tail < ia.size() - head && ib[ib.size() - 1 - tail] == ia[ia.size() - 1 - tail]) ++tail;
    const std::size_t n = ib.size() - head - tail, m = ia.size() - head - tail;
    if (n * m > 4'000'000) return false;
    std::vector<std::size_t> lcs((n + 1) * (m + 1), 0);
    const auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return lcs[i * (m + 1) + j]; };
    for (std::size_t i = n; i-- > 0;) {
      for (std::size_t j = m; j-- > 0;) {
        at(i, j) = ib[head + i] == ia[head + j] ? at(i + 1, j + 1) + 1 : std::max(at(i + 1, j), at(i, j + 1));
      }
    }
    std::vector<std::pair<std::optional<std::size_t>, std::optional<std::size_t>>> steps;  // (b item, a item)
    for (std::size_t k = 0; k < head; ++k) steps.emplace_back(k, k);
    for (std::size_t i = 0, j = 0; i < n || j < m;) {
      if (i < n && j < m && ib[head + i] == ia[head + j]) {
        steps.emplace_back(head + i++, head + j++);
      } else if (j < m && (i == n || at(i, j + 1) >= at(i + 1, j))) {
        steps.emplace_back(std::nullopt, head + j++);
      } else {
        steps.emplace_back(head + i++, std::nullopt);
      }
    }
    for (std::size_t k = 0; k < tail; ++k) steps.emplace_back(ib.size() - tail + k, ia.size() - tail + k);
    const std::size_t column = spans->empty() ? 0 : spans->front().column;
    std::optional<std::size_t> anchor;
    if (!spans->empty()) anchor = spans->front().lead;
    for (const auto& [bk, ak] : steps) {
      if (bk && !ak) {
        edit((*spans)[*bk].lead, (*spans)[*bk].end, {});
        continue;
      }
      if (!bk) {
        auto text = moved((*a_spans)[*ak], column);
        if (!anchor || !text) return false;
        insert(*anchor, std::string(column, ' ') + *text);
        continue;
      }
      const Span& span = (*spans)[*bk];
      anchor = span.end;
      if (same(bi[*bk].value, ai[*ak].value)) continue;
      const std::size_t a_at = *ak;  // a structured binding cannot be captured (C++20, clang)
      const bool done = changed(oi[*bk].value, bi[*bk].value, ai[a_at].value, [&] {
        auto text = moved((*a_spans)[a_at], column);
        if (!text) return false;
        replace(span, std::move(*text));
        return true;
      });
      if (!done) return false;
    }
    return true;
  }

  Lines o_;
  Lines a_;
  bool crlf_ = false;
  std::vector<Edit> edits_;
};

}  // namespace

std::optional<std::string> keepLayout(const std::string& original, const std::string& before, const std::string& after) {
  try {
    const YAML::Node o = YAML::Load(original), b = YAML::Load(before), a = YAML::Load(after);
    Merger merger(original, after);
    if (!merger.map(o, b, a)) return std::nullopt;
    return merger.result();
  } catch (const YAML::Exception&) {
    return std::nullopt;  // a text yaml-cpp reads otherwise than the model reader did
  }
}

}  // namespace gdpn::model::detail
