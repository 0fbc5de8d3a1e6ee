// test_cdr_writer.cpp: ROS 2's CDR (cdr_writer.hpp): the encapsulation header, every primitive
// aligned to its size counted from the header's end (not from the buffer's start), strings with
// their NUL counted, sequences' counts, no padding for an empty sequence of float64 (Fast-CDR's
// and @foxglove/cdr's reading), and a whole message laid out byte for byte.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/io/cdr_writer.hpp"
#include "rodshape/io/ros_messages.hpp"

namespace rodshape {
namespace test_cdr_writer {
namespace {

std::string bytes_of(std::initializer_list<int> values) {
  std::string out;
  for (const int v : values) out.push_back(static_cast<char>(v));
  return out;
}

double float64_at(const std::string& buffer, std::size_t at) {
  double value = 0;
  std::memcpy(&value, buffer.data() + at, 8);
  return value;
}

TEST(CdrWriter, BeginsWithTheLittleEndianEncapsulationHeader) {
  CdrWriter out;
  EXPECT_EQ(out.bytes(), bytes_of({0x00, 0x01, 0x00, 0x00}));
  EXPECT_EQ(out.offset(), 0U);
}

TEST(CdrWriter, AlignsAFloat64ToEightBytesCountedFromTheHeadersEnd) {
  CdrWriter out;
  out.write_uint8(7);
  out.write_float64(1.5);
  // 4 header bytes, the uint8, 7 bytes of padding (offset 1 -> 8 after the header), the double:
  // aligned from the buffer's start it would begin at byte 8, not 12.
  ASSERT_EQ(out.bytes().size(), 4U + 1U + 7U + 8U);
  EXPECT_EQ(out.bytes()[4], '\x07');
  EXPECT_EQ(out.bytes().substr(5, 7), std::string(7, '\0'));
  EXPECT_EQ(float64_at(out.bytes(), 12), 1.5);
}

TEST(CdrWriter, AlignsFourByteValuesToFourAndBytesNotAtAll) {
  CdrWriter out;
  out.write_bool(true);
  out.write_uint8(2);
  out.write_uint32(0x01020304U);
  out.write_uint8(9);
  out.write_int32(-1);
  EXPECT_EQ(out.bytes(), bytes_of({0, 1, 0, 0,                         // header
                                   1, 2, 0, 0, 4,   3,   2,   1,       // bool, uint8, pad, uint32
                                   9, 0, 0, 0, 255, 255, 255, 255}));  // uint8, pad, int32
}

TEST(CdrWriter, AStringCountsItsTerminatingNul) {
  CdrWriter out;
  out.write_string("ab");
  out.write_string("");
  EXPECT_EQ(out.bytes(), bytes_of({0, 1, 0, 0, 3, 0, 0, 0, 'a', 'b', 0,  // "ab"
                                   0,                                    // pad to 4
                                   1, 0, 0, 0, 0}));                     // "": length 1, NUL
}

TEST(CdrWriter, AnEmptyFloat64SequenceAddsNoPadding) {
  CdrWriter out;
  out.write_float64_sequence({});
  out.write_uint32(5);
  // The count (0) then at once the next value: an 8-byte alignment here would put the 5 at 8.
  EXPECT_EQ(out.bytes(), bytes_of({0, 1, 0, 0, 0, 0, 0, 0, 5, 0, 0, 0}));
}

TEST(CdrWriter, AFloat64SequencePadsAfterItsCount) {
  CdrWriter out;
  const std::vector<double> values = {0.25, -2.0};
  out.write_float64_sequence(values);
  ASSERT_EQ(out.bytes().size(), 4U + 4U + 4U + 16U);  // count at 0, padding, values at 8 and 16
  EXPECT_EQ(out.bytes().substr(4, 8), bytes_of({2, 0, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(float64_at(out.bytes(), 12), 0.25);
  EXPECT_EQ(float64_at(out.bytes(), 20), -2.0);
}

TEST(CdrWriter, AUint8SequenceIsItsCountAndItsBytes) {
  CdrWriter out;
  out.write_uint8_sequence(std::string("\x01\x02\x03", 3));
  out.write_bool(false);
  EXPECT_EQ(out.bytes(), bytes_of({0, 1, 0, 0, 3, 0, 0, 0, 1, 2, 3, 0}));
}

TEST(RosMessages, AJointStateIsLaidOutFieldByField) {
  RosJointState state;
  state.header = {{12, 500}, "w"};
  state.name = {"j"};
  state.position = {0.5};
  const std::string cdr = ros_cdr(state);
  std::string expected = bytes_of({0,    1, 0, 0,          // header
                                   12,   0, 0, 0,          // stamp.sec (offset 0)
                                   0xF4, 1, 0, 0,          // stamp.nanosec = 500
                                   2,    0, 0, 0, 'w', 0,  // frame_id "w" (offset 8)
                                   0,    0,                // pad to 16
                                   1,    0, 0, 0,          // name: 1 string
                                   2,    0, 0, 0, 'j', 0,  // "j" (offset 20)
                                   0,    0,                // pad to 28
                                   1,    0, 0, 0});        // position: 1 value (offset 28)
  // The double at offset 32, a multiple of 8 already: no padding.
  double half = 0.5;
  expected.append(reinterpret_cast<const char*>(&half), 8);
  expected += bytes_of({0, 0, 0, 0, 0, 0, 0, 0});  // velocity, effort: empty, no padding
  EXPECT_EQ(cdr, expected);
}

TEST(RosMessages, TimeIsRoundedToTheNanosecondAndNegativeTimeRefused) {
  const RosTime t = RosTime::from_seconds(1.25);
  EXPECT_EQ(t.sec, 1);
  EXPECT_EQ(t.nanosec, 250000000U);
  EXPECT_EQ(RosTime::from_seconds(2.0 - 1e-10).nanoseconds(), 2000000000ULL);
  EXPECT_EQ(RosTime::from_seconds(0.9999999996).nanoseconds(), 1000000000ULL);
  EXPECT_THROW(RosTime::from_seconds(-1e-3), InputError);
}

TEST(RosMessages, ASchemaListsEachTypeItUsesOnceAfterItsOwnText) {
  const std::string schema = ros_schema("visualization_msgs/msg/MarkerArray");
  EXPECT_TRUE(schema.starts_with("Marker[] markers\n"));
  const std::string separator = std::string(80, '=') + "\nMSG: ";
  for (const char* type :
       {"visualization_msgs/msg/Marker", "std_msgs/msg/Header", "builtin_interfaces/msg/Time",
        "geometry_msgs/msg/Pose", "geometry_msgs/msg/Point", "geometry_msgs/msg/Quaternion",
        "std_msgs/msg/ColorRGBA", "builtin_interfaces/msg/Duration",
        "sensor_msgs/msg/CompressedImage", "visualization_msgs/msg/UVCoordinate",
        "visualization_msgs/msg/MeshFile", "geometry_msgs/msg/Vector3"}) {
    std::string name = type;  // headed as the fields spell it: "std_msgs/Header"
    name.erase(name.find("/msg/"), 4);
    const std::string heading = separator + name + "\n";
    const std::size_t at = schema.find(heading);
    ASSERT_NE(at, std::string::npos) << type;
    EXPECT_EQ(schema.find(heading, at + 1), std::string::npos) << type << " twice";
  }
  EXPECT_THROW(ros_schema("std_msgs/msg/String"), InputError);
}

}  // namespace
}  // namespace test_cdr_writer
}  // namespace rodshape
