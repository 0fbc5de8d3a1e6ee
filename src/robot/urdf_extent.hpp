// urdf_extent.hpp (private to the robot area): bounds on a URDF's text checked before urdfdom
// parses it. urdfdom's XML parser (TinyXML) recurses once per nesting level, takes time quadratic
// in the depth (a minute at 30,000 levels) and overflows the stack near 100,000; urdfdom's link
// tree overflows it for chains of some 100,000 links. A URDF is a few levels deep (robot, link,
// visual, geometry, mesh) and has tens of links.
#pragma once

#include <string>

namespace rodshape::robot_detail {

/// The deepest nesting of XML elements accepted in a URDF.
inline constexpr int kMaxUrdfDepth = 64;
/// The most <link> elements accepted in a URDF.
inline constexpr int kMaxUrdfLinks = 10000;

/// Throws InputError "<source>:<line>: the URDF does not parse: XML elements nested deeper than 64
/// levels" (or "more than 10000 links") when the text exceeds either bound. Text that is not
/// well-formed XML is left to the parser's own message.
void check_urdf_extent(const std::string& xml, const std::string& source);

}  // namespace rodshape::robot_detail
