// yaml_document.cpp: checks of the text before yaml-cpp reads it, and yaml-cpp's exceptions mapped
// to messages a user understands.
#include "io/yaml_document.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "rodshape/error.hpp"

namespace rodshape::io_detail {

namespace {

[[noreturn]] void fail_at(const std::string& source, int line, const std::string& what) {
  throw InputError(source + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what);
}

/// The length of the UTF-8 sequence at `i` and its code point, or nullopt when the bytes there
/// are not well-formed UTF-8 (overlong forms, surrogates and code points above U+10FFFF are not).
std::optional<std::pair<std::size_t, std::uint32_t>> decode_utf8(std::string_view text,
                                                                 std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  std::uint32_t point = 0, lowest = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2, point = lead & 0x1Fu, lowest = 0x80;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3, point = lead & 0x0Fu, lowest = 0x800;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4, point = lead & 0x07u, lowest = 0x10000;
  } else {
    return std::nullopt;
  }
  if (i + length > text.size()) return std::nullopt;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0u) != 0x80u) return std::nullopt;
    point = (point << 6) | (byte(i + k) & 0x3Fu);
  }
  if (point < lowest || point > 0x10FFFF || (point >= 0xD800 && point <= 0xDFFF))
    return std::nullopt;
  return std::make_pair(length, point);
}

/// YAML is printable Unicode text (YAML 1.2, 5.1): of the control characters only tab, line feed,
/// carriage return and next line are allowed. The text must be UTF-8 (a byte order mark may
/// start it).
void check_text(const std::string& text, const std::string& source) {
  const auto fail_byte = [&](int line, unsigned char byte) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(byte));
    fail_at(
        source, line,
        std::string("not a text file: invalid byte ") + hex + " (a task file is YAML, in UTF-8)");
  };
  int line = 1;
  std::size_t i = std::string_view(text).starts_with("\xEF\xBB\xBF") ? 3 : 0;
  while (i < text.size()) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x80) {
      if (byte == '\n') {
        ++line;
      } else if ((byte < 0x20 && byte != '\t' && byte != '\r') || byte == 0x7F) {
        fail_byte(line, byte);
      }
      ++i;
      continue;
    }
    const auto sequence = decode_utf8(text, i);
    if (!sequence) fail_byte(line, byte);
    const auto [length, point] = *sequence;
    if (point >= 0x80 && point < 0xA0 && point != 0x85) fail_byte(line, byte);  // C1 controls
    i += length;
  }
}

/// The 1-based lines of `text`, as views without their line break.
std::vector<std::string_view> lines_of(const std::string& text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = text.find('\n', start);
    lines.push_back(std::string_view(text).substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

/// The first line up to `last` (1-based) whose indentation holds a tab, or 0.
int first_tab_indented_line(const std::string& text, int last) {
  const std::vector<std::string_view> lines = lines_of(text);
  for (int k = 0; k < last && k < static_cast<int>(lines.size()); ++k) {
    const std::string_view line = lines[static_cast<std::size_t>(k)];
    const std::size_t indent_end = line.find_first_not_of(" \t");
    const std::string_view indent = line.substr(0, indent_end);
    if (indent_end != std::string_view::npos && indent.find('\t') != std::string_view::npos)
      return k + 1;
  }
  return 0;
}

/// YAML 1.2, 7.4.1: an implicit key is at most 1024 characters; yaml-cpp reads a longer one as a
/// plain scalar and then fails at its ':' with "illegal map value". The first line up to `last`
/// (1-based) whose text before its first ': ' (or final ':') is longer, or 0.
int first_overlong_key_line(const std::string& text, int last) {
  constexpr std::size_t kMaxImplicitKey = 1024;
  const std::vector<std::string_view> lines = lines_of(text);
  for (int k = 0; k < last && k < static_cast<int>(lines.size()); ++k) {
    std::string_view line = lines[static_cast<std::size_t>(k)];
    if (line.ends_with('\r')) line.remove_suffix(1);
    std::size_t colon = line.find(": ");
    if (colon == std::string_view::npos && line.ends_with(':')) colon = line.size() - 1;
    if (colon == std::string_view::npos) continue;
    const std::size_t start = std::min(line.find_first_not_of(" -"), colon);
    if (colon - start > kMaxImplicitKey) return k + 1;
  }
  return 0;
}

int line_of(const YAML::Mark& mark) { return mark.is_null() ? 0 : mark.line + 1; }

/// Builds nothing; keeps where the document started.
class DocumentStart final : public YAML::EventHandler {
 public:
  std::optional<YAML::Mark> mark;
  void OnDocumentStart(const YAML::Mark& at) override { mark = at; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&,
                const std::string&,
                YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&,
                       const std::string&,
                       YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&,
                  const std::string&,
                  YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

/// Where a document after the first starts, if there is one. yaml-cpp's Load() reads the first
/// document only, and ends it early, silently, at text it cannot fit into it; a second pass over
/// the events (cheap: no nodes are built) finds what follows. (Not YAML::LoadAll: yaml-cpp 0.7
/// loops forever on text such as ",$# #T".)
std::optional<YAML::Mark> second_document(const std::string& text) {
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  DocumentStart first, second;
  if (!parser.HandleNextDocument(first) || !parser.HandleNextDocument(second)) return std::nullopt;
  return second.mark;
}

}  // namespace

YAML::Node load_single_document(const std::string& text, const std::string& source) {
  check_text(text, source);
  try {
    YAML::Node root = YAML::Load(text);
    if (const std::optional<YAML::Mark> second = second_document(text)) {
      const int line = line_of(*second);
      const std::vector<std::string_view> lines = lines_of(text);
      const std::size_t row = static_cast<std::size_t>(std::max(line, 1) - 1);
      const auto column = static_cast<std::size_t>(std::max(second->column, 0));
      const bool marked = row < lines.size() && column <= lines[row].size() &&
                          lines[row].substr(column).starts_with("---");
      fail_at(source, line,
              marked ? "a second YAML document starts here (after '---'); a task file is a single "
                       "document"
                     : "malformed YAML: text after the end of the document (check the "
                       "indentation)");
    }
    return root;
  } catch (const YAML::DeepRecursion& error) {
    fail_at(source, line_of(error.mark),
            "lists and mappings nested too deeply (the YAML reader stops at about 500 levels)");
  } catch (const YAML::Exception& error) {
    const int line = line_of(error.mark);
    if (const int tab_line = first_tab_indented_line(text, line > 0 ? line + 1 : 1 << 30)) {
      fail_at(source, tab_line,
              "malformed YAML: tab characters are not allowed for indentation in YAML; indent "
              "with spaces");
    }
    if (const int key_line = first_overlong_key_line(text, line > 0 ? line : 1 << 30)) {
      fail_at(source, key_line,
              "malformed YAML: a key longer than 1024 characters (YAML's limit for a key; a task "
              "file's keys are short names such as rod.length)");
    }
    fail_at(source, line, "malformed YAML: " + error.msg);
  }
}

}  // namespace rodshape::io_detail
