// ply_cloud.cpp: a cloud as PLY (cloud_reader.hpp): the header's elements and properties, then the
// vertex element's x, y, z, in ascii or binary of either byte order. Elements before the vertices
// are skipped (in binary, only those of fixed-size properties); those after are not read.
#include <array>
#include <string>

#include "io/cloud_text.hpp"

namespace rodshape::io_detail {

namespace {

struct PlyProperty {
  std::string name;
  int size = 0;  // bytes
  ScalarKind kind = ScalarKind::Float;
  bool list = false;
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, Little, Big };

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;  // where the body starts
  int body_line = 0;            // the header's last line
};

/// A scalar type's size and kind; false for an unknown name.
bool scalar_type(std::string_view type, int& size, ScalarKind& kind) {
  struct Type {
    std::string_view a, b;
    int size;
    ScalarKind kind;
  };
  static constexpr std::array<Type, 8> kTypes = {{
      {"char", "int8", 1, ScalarKind::Signed},
      {"uchar", "uint8", 1, ScalarKind::Unsigned},
      {"short", "int16", 2, ScalarKind::Signed},
      {"ushort", "uint16", 2, ScalarKind::Unsigned},
      {"int", "int32", 4, ScalarKind::Signed},
      {"uint", "uint32", 4, ScalarKind::Unsigned},
      {"float", "float32", 4, ScalarKind::Float},
      {"double", "float64", 8, ScalarKind::Float},
  }};
  for (const Type& t : kTypes)
    if (type == t.a || type == t.b) {
      size = t.size;
      kind = t.kind;
      return true;
    }
  return false;
}

PlyProperty read_property(const std::vector<std::string_view>& words,
                          const std::string& where,
                          const std::string& name) {
  PlyProperty p;
  ScalarKind ignored;
  int ignored_size;
  if (words.size() == 5 && words[1] == "list") {
    if (!scalar_type(words[2], ignored_size, ignored) || !scalar_type(words[3], p.size, p.kind))
      cloud_error(name, where + ": unknown type in a list property");
    p.list = true;
    p.name = std::string(words[4]);
    return p;
  }
  if (words.size() != 3 || !scalar_type(words[1], p.size, p.kind))
    cloud_error(name, where +
                          ": expected 'property TYPE NAME' with TYPE one of char, uchar, "
                          "short, ushort, int, uint, float, double");
  p.name = std::string(words[2]);
  return p;
}

PlyHeader read_header(std::string_view bytes, const std::string& name) {
  LineCursor lines(bytes);
  std::string_view line;
  if (!lines.next(line) || line != "ply") cloud_error(name, "line 1: not a PLY file (no 'ply')");
  PlyHeader header;
  bool format = false;
  while (true) {
    if (!lines.next(line)) cloud_error(name, "the header has no 'end_header'");
    const std::string where = "line " + std::to_string(lines.number());
    const std::vector<std::string_view> words = split_words(line);
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    if (words[0] == "end_header") break;
    if (words[0] == "format") {
      if (words.size() != 3 || words[2] != "1.0")
        cloud_error(name, where +
                              ": expected 'format ascii|binary_little_endian|"
                              "binary_big_endian 1.0'");
      if (words[1] == "ascii")
        header.format = PlyFormat::Ascii;
      else if (words[1] == "binary_little_endian")
        header.format = PlyFormat::Little;
      else if (words[1] == "binary_big_endian")
        header.format = PlyFormat::Big;
      else
        cloud_error(name, where + ": unknown format '" + std::string(words[1]) + "'");
      format = true;
    } else if (words[0] == "element") {
      PlyElement element;
      if (words.size() != 3 || !parse_count(words[2], SIZE_MAX, element.count))
        cloud_error(name, where + ": expected 'element NAME COUNT'");
      element.name = std::string(words[1]);
      header.elements.push_back(element);
    } else if (words[0] == "property") {
      if (header.elements.empty()) cloud_error(name, where + ": a property before any element");
      header.elements.back().properties.push_back(read_property(words, where, name));
    } else {
      cloud_error(name, where + ": unknown header keyword '" + std::string(words[0]) + "'");
    }
  }
  if (!format) cloud_error(name, "the header has no 'format' line");
  header.data_offset = lines.offset();
  header.body_line = lines.number();
  return header;
}

/// The vertex element's index and its x, y, z properties' indices.
struct VertexLayout {
  std::size_t element = 0;
  std::array<std::size_t, 3> xyz{};
};

VertexLayout vertex_layout(const PlyHeader& header, const std::string& name) {
  VertexLayout layout;
  bool found = false;
  for (std::size_t e = 0; e < header.elements.size() && !found; ++e)
    if (header.elements[e].name == "vertex") {
      layout.element = e;
      found = true;
    }
  if (!found) cloud_error(name, "the header has no 'element vertex'");
  const PlyElement& vertex = header.elements[layout.element];
  check_declared(vertex.count, name);
  const std::array<std::string_view, 3> axes = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    bool has = false;
    for (std::size_t p = 0; p < vertex.properties.size(); ++p) {
      const PlyProperty& property = vertex.properties[p];
      if (property.name != axes[k]) continue;
      if (property.list || property.kind != ScalarKind::Float)
        cloud_error(name, "vertex property " + property.name + " must be float or double");
      layout.xyz[k] = p;
      has = true;
    }
    if (!has) cloud_error(name, "the vertex element has no property " + std::string(axes[k]));
  }
  for (const PlyProperty& property : vertex.properties)
    if (property.list && header.format != PlyFormat::Ascii)
      cloud_error(name, "the vertex element has a list property (" + property.name +
                            "); binary vertices must have fixed-size properties");
  return layout;
}

std::vector<Eigen::Vector3d> read_ascii(std::string_view bytes,
                                        const PlyHeader& header,
                                        const VertexLayout& layout,
                                        const std::string& name) {
  LineCursor lines(bytes.substr(header.data_offset));
  std::vector<Eigen::Vector3d> points;
  std::string_view line;
  for (std::size_t e = 0; e <= layout.element; ++e) {
    const PlyElement& element = header.elements[e];
    for (std::size_t i = 0; i < element.count; ++i) {
      if (!lines.next(line))
        cloud_error(name, "the file ends after " + std::to_string(i) + " of " +
                              std::to_string(element.count) + " " + element.name + " lines");
      if (e != layout.element) continue;
      const std::string where = "line " + std::to_string(header.body_line + lines.number());
      const std::vector<std::string_view> words = split_words(line);
      std::vector<double> values;  // one per property (a list's values are skipped)
      std::size_t w = 0;
      for (const PlyProperty& property : element.properties) {
        std::size_t n = 0;
        if (property.list) {
          if (w >= words.size() || !parse_count(words[w], words.size(), n))
            cloud_error(name, where + ": bad list count for " + property.name);
          w += 1 + n;
          values.push_back(0.0);
          continue;
        }
        double value = 0.0;
        if (w >= words.size() || !parse_double(words[w], value))
          cloud_error(name, where + ": property " + property.name + " is missing or not a number");
        values.push_back(value);
        ++w;
      }
      if (w != words.size())
        cloud_error(name, where + ": " + std::to_string(words.size()) + " values, expected " +
                              std::to_string(w));
      add_point(points, values[layout.xyz[0]], values[layout.xyz[1]], values[layout.xyz[2]], name);
    }
  }
  return points;
}

std::vector<Eigen::Vector3d> read_binary(std::string_view bytes,
                                         const PlyHeader& header,
                                         const VertexLayout& layout,
                                         const std::string& name) {
  std::size_t offset = header.data_offset;
  for (std::size_t e = 0; e < layout.element; ++e) {  // skipped, if of fixed size
    std::size_t stride = 0;
    for (const PlyProperty& property : header.elements[e].properties) {
      if (property.list)
        cloud_error(name, "element " + header.elements[e].name +
                              " before the vertices has a list property; not supported in binary");
      stride += static_cast<std::size_t>(property.size);
    }
    const std::size_t available = bytes.size() - std::min(offset, bytes.size());
    if (stride > 0 && header.elements[e].count > available / stride)
      cloud_error(name, "the file ends within element " + header.elements[e].name);
    offset += stride * header.elements[e].count;
  }
  const PlyElement& vertex = header.elements[layout.element];
  std::vector<std::size_t> at;  // each property's offset within a vertex
  std::size_t stride = 0;
  for (const PlyProperty& property : vertex.properties) {
    at.push_back(stride);
    stride += static_cast<std::size_t>(property.size);
  }
  const std::size_t available = bytes.size() - std::min(offset, bytes.size());
  if (vertex.count > 0 && (stride == 0 || vertex.count > available / stride))
    cloud_error(name, "the file ends within the vertices: " + std::to_string(vertex.count) +
                          " vertices of " + std::to_string(stride) + " bytes need " +
                          std::to_string(vertex.count * stride) + ", " + std::to_string(available) +
                          " are left");
  const bool big = header.format == PlyFormat::Big;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data()) + offset;
  std::vector<Eigen::Vector3d> points;
  points.reserve(vertex.count);
  for (std::size_t i = 0; i < vertex.count; ++i, data += stride) {
    double xyz[3];
    for (int k = 0; k < 3; ++k) {
      const PlyProperty& p = vertex.properties[layout.xyz[k]];
      xyz[k] = read_scalar(data + at[layout.xyz[k]], p.size, p.kind, big);
    }
    add_point(points, xyz[0], xyz[1], xyz[2], name);
  }
  return points;
}

}  // namespace

std::vector<Eigen::Vector3d> parse_ply(std::string_view bytes, const std::string& name) {
  const PlyHeader header = read_header(bytes, name);
  const VertexLayout layout = vertex_layout(header, name);
  if (header.format == PlyFormat::Ascii) return read_ascii(bytes, header, layout, name);
  return read_binary(bytes, header, layout, name);
}

}  // namespace rodshape::io_detail
