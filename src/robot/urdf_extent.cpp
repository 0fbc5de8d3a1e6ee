// urdf_extent.cpp: one pass over the XML text counting open elements and <link> elements; comments,
// CDATA sections, declarations and processing instructions are skipped, quoted attribute values
// may hold '>'.
#include "robot/urdf_extent.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "rodshape/error.hpp"

namespace rodshape::robot_detail {

namespace {

class XmlScanner {
 public:
  XmlScanner(const std::string& xml, const std::string& source) : xml_(xml), source_(source) {}

  void run() {
    for (std::size_t i = xml_.find('<'); i != std::string::npos; i = xml_.find('<', i)) {
      i = markup(i);
      if (i == std::string::npos) return;  // unterminated: the parser will say so
    }
  }

 private:
  /// Handles the markup starting at `start` ('<'); returns the position after it.
  std::size_t markup(std::size_t start) {
    const std::string_view rest = std::string_view(xml_).substr(start);
    if (rest.starts_with("<!--")) return past(start, "-->");
    if (rest.starts_with("<![CDATA[")) return past(start, "]]>");
    if (rest.starts_with("<?") || rest.starts_with("<!")) return past(start, ">");
    if (rest.starts_with("</")) {
      --depth_;
      return past(start, ">");
    }
    std::size_t end = start + 1;
    while (end < xml_.size() && (std::isalnum(static_cast<unsigned char>(xml_[end])) ||
                                 xml_[end] == '_' || xml_[end] == ':' || xml_[end] == '-'))
      ++end;
    const std::string_view name = std::string_view(xml_).substr(start + 1, end - start - 1);
    // The end of the tag, outside quoted attribute values.
    char quote = 0;
    for (; end < xml_.size(); ++end) {
      const char c = xml_[end];
      if (quote != 0) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '>') {
        break;
      }
    }
    if (end >= xml_.size()) return std::string::npos;
    const bool empty_element = xml_[end - 1] == '/';
    if (name == "link" && ++links_ > kMaxUrdfLinks)
      fail(start, "more than " + std::to_string(kMaxUrdfLinks) + " links");
    if (!empty_element && ++depth_ > kMaxUrdfDepth)
      fail(start, "XML elements nested deeper than " + std::to_string(kMaxUrdfDepth) + " levels");
    return end + 1;
  }

  /// The position after the first `terminator` from `start`, or npos.
  std::size_t past(std::size_t start, std::string_view terminator) const {
    const std::size_t end = xml_.find(terminator, start + 1);
    return end == std::string::npos ? end : end + terminator.size();
  }

  [[noreturn]] void fail(std::size_t position, const std::string& what) const {
    const auto line = 1 + std::count(xml_.begin(), xml_.begin() + position, '\n');
    throw InputError(source_ + ":" + std::to_string(line) + ": the URDF does not parse: " + what);
  }

  const std::string& xml_;
  const std::string& source_;
  int depth_ = 0;
  int links_ = 0;
};

}  // namespace

void check_urdf_extent(const std::string& xml, const std::string& source) {
  XmlScanner(xml, source).run();
}

}  // namespace rodshape::robot_detail
