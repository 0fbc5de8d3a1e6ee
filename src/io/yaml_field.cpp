// yaml_field.cpp: YamlField, the checked reading of one YAML value with its path and line.
#include "io/yaml_field.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <system_error>

#include "io/did_you_mean.hpp"
#include "io/yaml_document.hpp"
#include "validation.hpp"

namespace rodshape::io_detail {

namespace {

/// yaml-cpp marks are 0-based and -1 when unknown; ours are 1-based and 0 when unknown.
int line_of(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

/// A YAML 1.2 core-schema float: decimal or exponent notation, or .inf, -.inf, .nan (any of
/// their three spellings). nullopt when the text is not a number.
std::optional<double> parse_number(std::string_view text) {
  std::string_view body = text;
  bool negative = false;
  if (!body.empty() && (body.front() == '+' || body.front() == '-')) {
    negative = body.front() == '-';
    body.remove_prefix(1);
  }
  if (body == ".inf" || body == ".Inf" || body == ".INF") {
    return negative ? -std::numeric_limits<double>::infinity()
                    : std::numeric_limits<double>::infinity();
  }
  if (text == ".nan" || text == ".NaN" || text == ".NAN") {
    return std::numeric_limits<double>::quiet_NaN();
  }
  // from_chars takes no '+' and no whitespace; a sign inside the body ("+-1") is an error.
  if (body.empty() || body.front() == '+' || body.front() == '-') return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(body.data(), body.data() + body.size(), value);
  if (end != body.data() + body.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) {
    // Overflow reads as infinity (rejected as not finite); underflow as zero.
    value = std::abs(std::strtod(std::string(body).c_str(), nullptr));
  } else if (error != std::errc()) {
    return std::nullopt;
  }
  return negative ? -value : value;
}

/// One component of a field path: "section" or "released[2]".
struct PathStep {
  std::string key;
  std::optional<std::size_t> index;
};

std::vector<PathStep> split_path(std::string_view path) {
  std::vector<PathStep> steps;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = path.find('.', start);
    const std::string_view part =
        path.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start);
    PathStep step;
    const std::size_t bracket = part.find('[');
    step.key = std::string(part.substr(0, bracket));
    if (bracket != std::string_view::npos) {
      std::size_t index = 0;
      const auto [end, error] =
          std::from_chars(part.data() + bracket + 1, part.data() + part.size(), index);
      if (error == std::errc() && end < part.data() + part.size() && *end == ']')
        step.index = index;
    }
    steps.push_back(std::move(step));
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return steps;
}

/// The key and value nodes of `key` in a mapping, found by comparing the keys' text.
std::optional<std::pair<YAML::Node, YAML::Node>> find_key(const YAML::Node& map,
                                                          std::string_view key) {
  if (!map.IsMap()) return std::nullopt;
  for (const auto& entry : map) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key) {
      return std::make_pair(entry.first, entry.second);
    }
  }
  return std::nullopt;
}

/// The leading field path of a library message: "rod.stiffness.EIx = 0 must be > 0" gives
/// "rod.stiffness.EIx".
std::string_view leading_path(std::string_view message) {
  std::size_t end = 0;
  while (end < message.size()) {
    const char c = message[end];
    const bool path_char =
        std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '[' || c == ']';
    if (!path_char) break;
    ++end;
  }
  return message.substr(0, end);
}

}  // namespace

YamlField::YamlField(std::shared_ptr<const YamlDocument> document)
    : document_(std::move(document)), node_(document_->root), path_(), line_(0), present_(true) {}

YamlField::YamlField(std::shared_ptr<const YamlDocument> document,
                     YAML::Node node,
                     std::string path,
                     int line,
                     bool present)
    : document_(std::move(document)),
      node_(std::move(node)),
      path_(std::move(path)),
      line_(line),
      present_(present) {}

YamlField YamlField::child(const YAML::Node& node, std::string path, int line) const {
  return YamlField(document_, node, std::move(path), line != 0 ? line : line_, true);
}

void YamlField::fail(const std::string& message) const {
  const std::string location =
      line_ > 0 ? document_->source + ":" + std::to_string(line_) : document_->source;
  throw InputError(location + ": " + message);
}

void YamlField::fail_value(const std::string& what) const {
  if (present_ && node_.IsScalar()) {
    const bool quoted = node_.Tag() == "!";
    const std::string value = quoted ? "\"" + node_.Scalar() + "\"" : node_.Scalar();
    fail(path_ + " = " + value + " " + what);
  }
  fail(path_ + " " + what);
}

std::string YamlField::describe() const {
  if (!present_) return "nothing";
  switch (node_.Type()) {
    case YAML::NodeType::Map:
      return "a mapping";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Scalar:
      return node_.Tag() == "!" ? "the string \"" + node_.Scalar() + "\""
                                : "'" + node_.Scalar() + "'";
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      break;
  }
  return "nothing";
}

// ---- mappings -----------------------------------------------------------------------------------

void YamlField::expect_mapping(const std::vector<std::string_view>& allowed,
                               const std::vector<KeyHint>& hints) const {
  const std::string name = path_.empty() ? "the task file" : path_;
  if (!present_ || !node_.IsMap()) {
    fail(name + ": expected a mapping with keys " + join_words(allowed) + ", got " + describe());
  }
  std::vector<std::pair<std::string, int>> seen;
  for (const auto& entry : node_) {
    const YamlField key_field = child(entry.first, path_, line_of(entry.first));
    if (!entry.first.IsScalar())
      key_field.fail(name + ": a key must be a name, got " + key_field.describe());
    const std::string& key = entry.first.Scalar();
    const std::string key_path = path_.empty() ? key : path_ + "." + key;
    const YamlField key_at = child(entry.first, key_path, line_of(entry.first));
    for (const auto& [previous, previous_line] : seen) {
      if (previous == key) {
        key_at.fail(key_path + ": duplicate key (first given on line " +
                    std::to_string(previous_line) + ")");
      }
    }
    seen.emplace_back(key, key_at.line());
    // YAML 1.1's merge key; yaml-cpp reads it as an ordinary key named "<<".
    if (key == "<<")
      key_at.fail(key_path +
                  ": YAML merge keys ('<<') are not supported in task files: write the keys out "
                  "(anchors and aliases of whole values, &name and *name, are supported)");
    bool known = false;
    for (const std::string_view word : allowed) known = known || word == key;
    if (known) continue;
    for (const KeyHint& hint : hints) {
      if (hint.key == key) key_at.fail(key_path + ": unknown key; " + std::string(hint.hint));
    }
    if (const auto suggestion = closest_match(key, allowed)) {
      key_at.fail(key_path + ": unknown key; did you mean '" + *suggestion + "'?");
    }
    key_at.fail(key_path + ": unknown key; expected one of " + join_words(allowed));
  }
}

std::map<std::string, int> YamlField::key_lines(int depth) const {
  std::map<std::string, int> lines;
  if (depth < 1 || !present_ || !node_.IsMap()) return lines;
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar()) continue;
    const YamlField value = get(entry.first.Scalar());
    lines.emplace(value.path(), line_of(entry.first));
    lines.merge(value.key_lines(depth - 1));
  }
  return lines;
}

YamlField YamlField::get(std::string_view key) const {
  const std::string key_path = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  if (!present_ || !node_.IsMap()) {
    fail((path_.empty() ? std::string("the task file") : path_) + ": expected a mapping, got " +
         describe());
  }
  // A value is reported at its key's line: a block mapping or list starts on the line after it.
  if (const auto entry = find_key(node_, key))
    return child(entry->second, key_path, line_of(entry->first));
  return YamlField(document_, YAML::Node(), key_path, line_, false);
}

YamlField YamlField::require(std::string_view key) const {
  YamlField value = get(key);
  if (!value.present()) fail(value.path() + " is required");
  return value;
}

// ---- sequences ----------------------------------------------------------------------------------

std::vector<YamlField> YamlField::elements() const {
  if (!present_ || !node_.IsSequence()) fail(path_ + ": expected a list, got " + describe());
  std::vector<YamlField> elements;
  elements.reserve(node_.size());
  std::size_t i = 0;
  for (const auto& element : node_) {
    elements.push_back(child(element, path_ + "[" + std::to_string(i) + "]", line_of(element)));
    ++i;
  }
  return elements;
}

// ---- scalars ------------------------------------------------------------------------------------

void YamlField::expect_scalar(std::string_view expected) const {
  if (!present_ || !node_.IsScalar()) {
    fail(path_ + ": expected " + std::string(expected) + ", got " + describe());
  }
}

double YamlField::number() const {
  expect_scalar("a number");
  if (node_.Tag() == "!") fail_value("is a quoted string; expected a number");
  const std::optional<double> value = parse_number(node_.Scalar());
  if (!value) fail_value("is not a number");
  if (!std::isfinite(*value)) fail_value("is not a finite number");
  return *value;
}

double YamlField::positive_number() const {
  const double value = number();
  if (!(value > 0.0)) fail_value("must be > 0");
  return value;
}

double YamlField::positive_number_at_most(double max) const {
  expect_scalar("a number");
  const std::optional<double> value =
      node_.Tag() == "!" ? std::nullopt : parse_number(node_.Scalar());
  if (value && *value > max) fail_value("must be <= " + detail::format_value(max));  // and .inf
  return positive_number();  // the other failures, as positive_number() says them
}

int YamlField::integer() const {
  const double value = number();
  if (value != std::floor(value)) fail_value("must be a whole number");
  if (std::abs(value) > std::numeric_limits<int>::max()) fail_value("is out of range");
  return static_cast<int>(value);
}

int YamlField::integer_in(int min, int max) const {
  const double value = number();
  if (value != std::floor(value)) fail_value("must be a whole number");
  if (value < min) fail_value("must be >= " + std::to_string(min));
  if (value > max) fail_value("must be <= " + std::to_string(max));
  return static_cast<int>(value);
}

bool YamlField::boolean() const {
  expect_scalar("true or false");
  bool value = false;
  if (node_.Tag() == "!" || !YAML::convert<bool>::decode(node_, value)) {
    fail_value("must be true or false");
  }
  return value;
}

std::string YamlField::text() const {
  expect_scalar("a name");
  return node_.Scalar();
}

std::string YamlField::choice(const std::vector<std::string_view>& choices) const {
  const std::string value = text();
  for (const std::string_view option : choices) {
    if (option == value) return value;
  }
  if (const auto suggestion = closest_match(value, choices)) {
    fail_value("is not allowed; did you mean '" + *suggestion + "'?");
  }
  fail_value("is not one of " + join_words(choices));
}

Eigen::Vector3d YamlField::vector3() const {
  if (!present_ || !node_.IsSequence() || node_.size() != 3) {
    fail(path_ + ": expected a list of 3 numbers [x, y, z], got " +
         (is_sequence() ? "a list of " + std::to_string(node_.size()) : describe()));
  }
  const std::vector<YamlField> xyz = elements();
  return {xyz[0].number(), xyz[1].number(), xyz[2].number()};
}

// ---- library errors -----------------------------------------------------------------------------

void YamlField::fail_located(const std::string& message) const {
  // Walk the document along the message's leading path, as deep as it goes.
  int line = 0;
  // (YAML::Node::operator= writes through to the document; reset() rebinds the handle.)
  YAML::Node node;
  node.reset(document_->root);
  for (const PathStep& step : split_path(leading_path(message))) {
    const auto entry = find_key(node, step.key);
    if (!entry) break;
    node.reset(entry->second);
    int step_line = line_of(entry->first);
    if (step.index && node.IsSequence() && *step.index < node.size()) {
      const YAML::Node sequence = node;
      node.reset(sequence[*step.index]);
      step_line = line_of(node);
    }
    if (step_line > 0) line = step_line;
  }
  YamlField located = *this;
  if (line > 0) located.line_ = line;
  located.fail(message);
}

// ---- parsing ------------------------------------------------------------------------------------

YamlField parse_yaml(const std::string& text, const std::string& source) {
  return YamlField(std::make_shared<const YamlDocument>(
      YamlDocument{source, load_single_document(text, source)}));
}

}  // namespace rodshape::io_detail
