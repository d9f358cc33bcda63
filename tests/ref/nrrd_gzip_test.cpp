// NRRD volumes are written gzip-encoded (ref/io/nrrd.cpp): the floats come back bit for bit, a
// mostly empty volume shrinks to a small fraction, raw files (another tool's, or vct's before)
// still read, and a gzip payload that is corrupt, short, long, or claims more than deflate can
// expand is one InputError naming the file, refused before anything that large is allocated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <zlib.h>

#include "core/error.h"
#include "core/volume.h"
#include "io/atomic_file.h"
#include "io/nrrd.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "vct_nrrd_gzip";
  fs::create_directories(dir);
  return (dir / name).string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void put(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// `raw` as one gzip member by zlib's own defaults (another writer than ours).
std::string gzip(const std::string& raw) {
  z_stream z{};
  deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&z, uLong(raw.size())) + 64, '\0');
  z.next_in = reinterpret_cast<unsigned char*>(const_cast<char*>(raw.data()));
  z.avail_in = uInt(raw.size());
  z.next_out = reinterpret_cast<unsigned char*>(out.data());
  z.avail_out = uInt(out.size());
  EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

std::string floats(size_t n, float v) {
  std::string s(n * 4, '\0');
  for (size_t i = 0; i < n; ++i) std::memcpy(&s[i * 4], &v, 4);
  return s;
}

std::string refusal(const std::string& path) {
  try {
    read_nrrd(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(read without error)";
}

TEST(NrrdGzip, RoundTripKeepsEveryBit) {
  Volume v(8, 4, 2, 4);
  for (size_t i = 0; i < v.data.size(); ++i) v.data[i] = float(i) * 0.37f - 11.0f;
  v.data[5] = -0.0f, v.data[6] = INFINITY, v.data[7] = std::ldexp(1.0f, -140);  // sign of zero, inf, subnormal
  const std::string path = scratch("round.nrrd");
  write_nrrd(path, v);
  EXPECT_NE(slurp(path).find("\nencoding: gzip\n\n"), std::string::npos);
  const Volume back = read_nrrd(path);
  ASSERT_EQ(back.data.size(), v.data.size());
  EXPECT_EQ(std::memcmp(back.data.data(), v.data.data(), v.data.size() * 4), 0);
  EXPECT_EQ(back.nx, 8);
  EXPECT_EQ(back.nz, 2);
  EXPECT_EQ(back.channels, 4);
}

TEST(NrrdGzip, AnEmptyVolumeIsSmallAndTheSameBytesTwice) {
  const Volume empty(64, 64, 64, 4);  // 4 MiB of zero floats
  const std::string a = scratch("empty_a.nrrd"), b = scratch("empty_b.nrrd");
  write_nrrd(a, empty);
  write_nrrd(b, empty);
  EXPECT_LT(slurp(a).size(), 64u * 64 * 64 * 16 / 500);  // deflate's runs: > 500:1
  EXPECT_EQ(slurp(a), slurp(b));                         // no time stamp: reruns are byte-identical
}

TEST(NrrdGzip, RawAndForeignGzipFilesRead) {
  const std::string head = "NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 2\nendian: little\n";
  put(scratch("raw.nrrd"), head + "encoding: raw\n\n" + floats(8, 1.5f));
  EXPECT_EQ(read_nrrd(scratch("raw.nrrd")).data, std::vector<float>(8, 1.5f));
  put(scratch("foreign.nrrd"), head + "encoding: gzip\n\n" + gzip(floats(8, -2.25f)));
  EXPECT_EQ(read_nrrd(scratch("foreign.nrrd")).data, std::vector<float>(8, -2.25f));
  put(scratch("gz.nrrd"), head + "encoding: gz\n\n" + gzip(floats(8, 3.0f)));  // teem's short name
  EXPECT_EQ(read_nrrd(scratch("gz.nrrd")).data, std::vector<float>(8, 3.0f));
}

TEST(NrrdGzip, BadPayloadsAreOneInputErrorNamingTheFile) {
  const std::string head = "NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 2\nendian: little\nencoding: gzip\n\n";
  const std::string path = scratch("bad.nrrd");
  put(path, head + "not a gzip stream at all");
  EXPECT_NE(refusal(path).find(path + ": NRRD gzip data is corrupt"), std::string::npos) << refusal(path);
  put(path, head + gzip(floats(7, 1.0f)));  // one float short
  EXPECT_NE(refusal(path).find("need 32 bytes, gzip decodes to 28"), std::string::npos) << refusal(path);
  put(path, head + gzip(floats(9, 1.0f)));  // one float too many
  EXPECT_NE(refusal(path).find("longer than the sizes"), std::string::npos) << refusal(path);
  const std::string whole = gzip(floats(8, 1.0f));
  put(path, head + whole.substr(0, whole.size() - 6));  // truncated: no end of stream
  EXPECT_NE(refusal(path).find("corrupt"), std::string::npos) << refusal(path);
}

TEST(NrrdGzip, AClaimDeflateCannotReachIsRefusedBeforeAllocating) {
  // 16 x 4096^3 floats (4 TiB) from a few bytes: more than deflate's 1032:1 can expand, refused
  // from the sizes alone.
  const std::string path = scratch("claims.nrrd");
  put(path, "NRRD0004\ntype: float\ndimension: 4\nsizes: 16 4096 4096 4096\nendian: little\nencoding: gzip\n\n" +
                gzip(floats(8, 0.0f)));
  EXPECT_NE(refusal(path).find("cannot decode to the 4398046511104 the sizes need"), std::string::npos)
      << refusal(path);
}

}  // namespace
}  // namespace vct
