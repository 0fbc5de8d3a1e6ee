// yaml_field.hpp (private to the io area): a YAML node together with its field path
// ("rod.section.width") and the file it came from, so that every error names both, on one line:
//   "<source>:<line>: <path> <what>"      e.g. "task.yaml:4: rod.length = -0.3 must be > 0".
// Lines are 1-based (yaml-cpp's Mark().line is 0-based). yaml-cpp stays out of the public headers.
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/io/field_names.hpp"

namespace rodshape::io_detail {

/// A parsed document and the name it is reported under.
struct YamlDocument {
  std::string source;
  YAML::Node root;
};

/// A key that is not allowed where it was found, and the hint to give instead of a spelling
/// suggestion, e.g. {"gravity", "gravity is a top-level section, not part of rod"}.
struct KeyHint {
  std::string_view key;
  std::string_view hint;
};

class YamlField {
 public:
  /// The document's root: path "" and no line (top-level keys get the paths "rod", "tip", ...).
  explicit YamlField(std::shared_ptr<const YamlDocument> document);
  YamlField(const YamlField&) = default;
  // No assignment: YAML::Node::operator= would write through into the document.
  YamlField& operator=(const YamlField&) = delete;

  const std::string& path() const { return path_; }
  const std::string& source() const { return document_->source; }
  /// 1-based line of the key (of the element, in a list), or of the enclosing mapping's key for an
  /// absent key; 0 when unknown (the root).
  int line() const { return line_; }
  /// The key exists (its value may still be empty).
  bool present() const { return present_; }

  /// Throws InputError "<source>:<line>: <message>".
  [[noreturn]] void fail(const std::string& message) const;
  /// fail("<path> <what>"), or fail("<path> = <value> <what>") for a scalar (its text as written).
  [[noreturn]] void fail_value(const std::string& what) const;

  // ---- mappings
  // ----------------------------------------------------------------------------------
  /// Requires a mapping with no duplicate keys, all of them in `allowed`. An unknown key fails with
  /// its hint if `hints` has one, else "did you mean '<closest>'?", else the list of allowed keys.
  void expect_mapping(const std::vector<std::string_view>& allowed,
                      const std::vector<KeyHint>& hints = {}) const;
  /// The value of `key`; absent (present() == false) when the mapping has no such key.
  YamlField get(std::string_view key) const;
  /// The value of `key`, which must be there: else fails "<path>.<key> is required".
  YamlField require(std::string_view key) const;
  bool has(std::string_view key) const { return get(key).present(); }

  /// The line of each key under this mapping, `depth` levels deep, by path ("initial.tip").
  std::map<std::string, int> key_lines(int depth) const;

  // ---- sequences
  // ---------------------------------------------------------------------------------
  /// Requires a sequence; its elements have paths "<path>[i]".
  std::vector<YamlField> elements() const;
  bool is_sequence() const { return present_ && node_.IsSequence(); }

  // ---- scalars
  // -----------------------------------------------------------------------------------
  /// A finite number (YAML .nan and .inf fail).
  double number() const;
  /// A finite number > 0.
  double positive_number() const;
  /// A finite number in (0, max], said as written when not; .inf is beyond max:
  /// "solver.integration_tolerance = .inf must be <= 1".
  double positive_number_at_most(double max) const;
  /// A whole number representable as int.
  int integer() const;
  /// A whole number in [min, max], said as written when not: "trajectory.steps = 1e9 must be <=
  /// 1000" (the bounds of docs/limits.md, "Sizes").
  int integer_in(int min, int max) const;
  /// true/false (also yes/no, on/off as yaml-cpp reads them).
  bool boolean() const;
  /// A plain or quoted string.
  std::string text() const;
  /// A string among `choices`, else "did you mean" or the list of choices.
  std::string choice(const std::vector<std::string_view>& choices) const;
  /// [x, y, z], each a finite number.
  Eigen::Vector3d vector3() const;

  /// Runs a library call that may throw InputError whose message starts with a field path
  /// ("rod.length = -0.3 must be > 0"; a library field is said in the task file's name, see
  /// field_names.hpp) and rethrows it with this file and the line of the deepest
  /// node of that path in the document (or of this field when the path is not in the document).
  template <class Call>
  decltype(auto) located(Call&& call) const {
    try {
      return std::forward<Call>(call)();
    } catch (const InputError& error) {
      fail_located(in_task_names(error));
    }
  }
  /// The same for a message already in hand.
  [[noreturn]] void fail_located(const std::string& message) const;

 private:
  YamlField(std::shared_ptr<const YamlDocument> document,
            YAML::Node node,
            std::string path,
            int line,
            bool present);

  /// A value inside this one, reported at `line` (this field's line when 0).
  YamlField child(const YAML::Node& node, std::string path, int line) const;
  /// What the node holds, for "expected a mapping, got a list".
  std::string describe() const;
  void expect_scalar(std::string_view expected) const;

  std::shared_ptr<const YamlDocument> document_;
  YAML::Node node_;
  std::string path_;
  int line_ = 0;
  bool present_ = false;
};

/// Parses `text` (reported as `source`), a single YAML document (yaml_document.hpp). Malformed YAML
/// throws InputError "<source>:<line>: malformed YAML: <reason>"; text that is not UTF-8 and a
/// second document throw with their own messages.
YamlField parse_yaml(const std::string& text, const std::string& source);

}  // namespace rodshape::io_detail
