// The LHT entry precisions (lht/table/lht_precision.hpp): each form's quantization
// round trip stays within the error bounds it documents, at the extremes
// (s = 0, 1/2, 1; normals along the axes, the diagonals, and both sides of
// the octahedral fold) and over a dense sample of the sphere.
#include <catch2/catch.hpp>

#include <limits>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "lht/table/entry_codec.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "lht/grid/octahedral.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

LhtHit roundTrip(LhtPrecision precision, double s, const Vec3d& normal) {
  std::vector<std::uint8_t> entry(entryBytes(precision), 0xEE);
  encodeEntry(RasterHit{{1, 2, 3}, {4, 5, 6}, s, normal}, precision, entry.data());
  // The key is the thesis's, and the overflow index is not the codec's to write.
  CHECK(entry[0] == 1);
  CHECK(entry[5] == 6);
  CHECK(std::all_of(entry.end() - kEntryNextBytes, entry.end(), [](std::uint8_t b) { return b == 0xEE; }));
  return decodeEntry(entry.data(), precision);
}

double angleDegrees(const Vec3d& a, const Vec3d& b) {
  // atan2 of |a x b| and a . b stays accurate for tiny angles, unlike acos.
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / std::numbers::pi;
}

double normalError(LhtPrecision precision, const Vec3d& unit) {
  return angleDegrees(roundTrip(precision, 0.5, unit).normal, unit);
}

// Unit vectors hugging the fold of the octahedral map (the equator z = 0,
// where the lower hemisphere is folded over the square's corners), on both
// sides, all the way round.
std::vector<Vec3d> foldDirections() {
  std::vector<Vec3d> out;
  for (int i = 0; i < 720; ++i) {
    const double phi = i * std::numbers::pi / 360.0;
    for (double z : {0.0, 1e-9, -1e-9, 1e-4, -1e-4, 0.01, -0.01})
      out.push_back(glm::normalize(Vec3d(std::cos(phi), std::sin(phi), z)));
  }
  return out;
}

}  // namespace

TEST_CASE("LHT precision: names and codes and entry sizes") {
  CHECK(entryBytes(LhtPrecision::Thesis) == 14);
  CHECK(entryBytes(LhtPrecision::Wide) == 16);
  CHECK(entryBytes(LhtPrecision::Compact) == 13);
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    CHECK(parseLhtPrecision(form.name) == form.precision);
    CHECK(lhtPrecisionName(form.precision) == form.name);
    CHECK(lhtPrecisionFromCode(static_cast<std::uint16_t>(form.precision)) == form.precision);
    // key + payload + next: the payload holds s's bits and the normal's.
    CHECK(form.entryBytes > kEntryKeyBytes + kEntryNextBytes);
  }
  CHECK(static_cast<int>(LhtPrecision::Thesis) == 0);  // what version-1 files hold at byte 18
  CHECK_FALSE(lhtPrecisionFromCode(3));
  CHECK_FALSE(lhtPrecisionFromName("Thesis"));
  try {
    parseLhtPrecision("huge", "--lht-precision");
    FAIL("an unknown precision was accepted");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Usage);
    const std::string message = e.what();
    CHECK(message.find("--lht-precision") != std::string::npos);
    CHECK(message.find("'huge'") != std::string::npos);
    CHECK(message.find("thesis (14 B/entry), wide (16 B/entry), compact (13 B/entry)") != std::string::npos);
  }
}

TEST_CASE("LHT precision: s round trips within half a step and is exact at 0 and 1") {
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    INFO(form.name);
    const Vec3d up(0, 0, 1);
    CHECK(roundTrip(form.precision, 0.0, up).s == 0.0);
    CHECK(roundTrip(form.precision, 1.0, up).s == 1.0);
    // 1/2 is not a multiple of 1/255 or 1/65535: it lands half a step away, the worst case.
    CHECK(std::abs(roundTrip(form.precision, 0.5, up).s - 0.5) == Approx(form.maxSError).epsilon(1e-9));
    CHECK(roundTrip(form.precision, -0.25, up).s == 0.0);  // clamped, not wrapped
    CHECK(roundTrip(form.precision, 1.25, up).s == 1.0);
    double worst = 0.0;
    for (int i = 0; i <= 100000; ++i) {
      const double s = i / 100000.0;
      worst = std::max(worst, std::abs(roundTrip(form.precision, s, up).s - s));
    }
    CHECK(worst <= form.maxSError * (1 + 1e-9));
    CHECK(worst >= 0.99 * form.maxSError);  // the bound is the real one, not a loose guess
  }
}

TEST_CASE("LHT precision: normals along the axes are exact and the diagonals within the bound") {
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    INFO(form.name);
    for (int a = 0; a < 3; ++a)
      for (double sign : {1.0, -1.0}) {
        Vec3d axis(0.0);
        axis[a] = sign;
        CHECK(roundTrip(form.precision, 0.5, axis).normal == axis);
      }
    for (double x : {1.0, -1.0})
      for (double y : {1.0, -1.0})
        for (double z : {1.0, -1.0}) {
          const Vec3d diagonal = glm::normalize(Vec3d(x, y, z));
          CHECK(normalError(form.precision, diagonal) <= form.maxNormalErrorDegrees);
        }
  }
}

TEST_CASE("LHT precision: normal error bounds hold over the sphere and at the octahedral fold") {
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    INFO(form.name);
    double worst = 0.0;
    for (const Vec3d& n : fibonacciSphere(200000)) worst = std::max(worst, normalError(form.precision, n));
    double worstAtFold = 0.0;
    for (const Vec3d& n : foldDirections()) worstAtFold = std::max(worstAtFold, normalError(form.precision, n));
    INFO("largest error " << worst << " degrees over the sphere, " << worstAtFold << " at the fold");
    CHECK(worst <= form.maxNormalErrorDegrees);
    CHECK(worstAtFold <= form.maxNormalErrorDegrees);
    CHECK(worst >= 0.8 * form.maxNormalErrorDegrees);  // the documented bound is tight
  }
}

TEST_CASE("LHT precision: octahedral codes decode to integer directions of L1 length m") {
  for (const std::int32_t m : {127, 32767}) {
    INFO("m = " << m);
    for (const Vec3d& n : {Vec3d(1, 0, 0), Vec3d(0, 0, -1), Vec3d(0.6, -0.8, 0), Vec3d(-0.3, 0.4, -0.866),
                           Vec3d(0.2, 0.1, 0.97)}) {
      const auto d = decodeOctahedral(encodeOctahedral(n, m), m);
      CHECK(std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]) == m);
      if (std::abs(n.z) > 1e-3) CHECK((d[2] < 0) == (n.z < 0));  // the hemisphere survives the fold
    }
    // Every code, even one a corrupt file holds, decodes to a non-zero direction in range.
    for (std::int32_t u : {-m - 1000, -m - 1, -m, -1, 0, 1, m / 2, m, m + 1})
      for (std::int32_t v : {-m - 1, -m, -3, 0, 7, m, m + 1000}) {
        const auto d = decodeOctahedral({u, v}, m);
        CHECK(std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]) == m);
        CHECK(std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])}) <= m);
      }
  }
}

TEST_CASE("LHT precision: any payload bytes decode to a usable fraction and direction") {
  // A checksum-valid but forged file may hold anything between key and next.
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    INFO(form.name);
    std::vector<std::uint8_t> entry(form.entryBytes, 0);
    const std::int32_t m = normalDirectionMax(form.precision);
    for (std::uint32_t pattern = 0; pattern < 65536; pattern += 7) {
      for (std::size_t i = kEntryKeyBytes; i + kEntryNextBytes < entry.size(); ++i)
        entry[i] = static_cast<std::uint8_t>((pattern * 2654435761u) >> (8 * (i % 4)));
      const EntryIntegers v = decodeEntryIntegers(entry.data(), form.precision);
      CHECK(v.sDenominator > 0);
      CHECK(v.sNumerator >= 0);
      CHECK(v.sNumerator <= v.sDenominator);
      CHECK((v.normal[0] != 0 || v.normal[1] != 0 || v.normal[2] != 0));
      CHECK(std::max({std::abs(v.normal[0]), std::abs(v.normal[1]), std::abs(v.normal[2])}) <= m);
    }
  }
}

TEST_CASE("LHT precision: a zero or non-finite normal encodes as +z, never as garbage") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Vec3d& bad : {Vec3d(0.0), Vec3d(nan, 0.0, 1.0), Vec3d(std::numeric_limits<double>::infinity(), 0, 0)}) {
    for (const std::int32_t m : {127, 32767}) {
      const OctahedralCode code = encodeOctahedral(bad, m);
      CHECK(code.u == 0);
      CHECK(code.v == 0);
      CHECK(decodeOctahedral(code, m) == std::array<std::int32_t, 3>{0, 0, m});
    }
  }
}
