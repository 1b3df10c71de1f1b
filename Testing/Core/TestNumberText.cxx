// Numbers as text whatever the host's locale (NumberText.h): the same text as
// printf in the C locale, and files, messages and reading unchanged under a
// locale whose decimal point is a comma (a review: a German one wrote
// "2 0,25 1,75 1" into .node files and read 1.5e-400 as 1).
#include "Clean.h"
#include "MeshWriter.h"
#include "Mesher.h"
#include "NumberText.h"
#include "PolyReader.h"

#include <gtest/gtest.h>

#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <stdlib.h> // mkdtemp, setenv
#include <string>

namespace osm
{
namespace
{
namespace fs = std::filesystem;

std::string printed(const char* format, double x)
{
  char buf[400];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

/// Sets LC_NUMERIC to German (a comma for the decimal point) while it lives:
/// made with localedef into a fresh folder of its own (a fresh machine may
/// have no German locale), removed with it; LOCPATH is restored. ok() is
/// false where that cannot be done.
class GermanNumbers
{
public:
  GermanNumbers()
  {
    std::string pattern = (fs::temp_directory_path() / "osm-locale-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      return;
    this->Dir = pattern;
    if (const char* before = std::getenv("LOCPATH"))
      this->Before = before;
    const std::string made = (this->Dir / "de_DE.UTF-8").string();
    const std::string command = "localedef -i de_DE -f UTF-8 '" + made + "' > /dev/null 2>&1";
    (void)std::system(command.c_str()); // warnings make it return 1 with a usable locale
    setenv("LOCPATH", this->Dir.c_str(), 1);
    this->Ok =
      std::setlocale(LC_NUMERIC, "de_DE.UTF-8") != nullptr && printed("%.2f", 0.25) == "0,25";
  }
  ~GermanNumbers()
  {
    std::setlocale(LC_NUMERIC, "C");
    if (this->Before)
      setenv("LOCPATH", this->Before->c_str(), 1);
    else
      unsetenv("LOCPATH");
    std::error_code ignored;
    if (!this->Dir.empty())
      fs::remove_all(this->Dir, ignored);
  }
  bool ok() const { return this->Ok; }
  /// The folder, for the test's own files.
  const fs::path& dir() const { return this->Dir; }

private:
  fs::path Dir;
  std::optional<std::string> Before;
  bool Ok = false;
};

TEST(NumberText, AsPrintfWritesInTheCLocale)
{
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> mantissa(-10, 10);
  std::uniform_int_distribution<int> exponent(-320, 300);
  for (int k = 0; k < 20000; ++k)
  {
    const double x = std::ldexp(mantissa(rng), exponent(rng));
    for (const int digits : { 2, 3, 6, 15, 16, 17 })
      ASSERT_EQ(generalText(x, digits), printed(("%." + std::to_string(digits) + "g").c_str(), x))
        << x;
    if (std::fabs(x) < 1e30)
      for (const int decimals : { 0, 2, 3 })
        ASSERT_EQ(
          fixedText(x, decimals), printed(("%." + std::to_string(decimals) + "f").c_str(), x))
          << x;
  }
  for (const double x : { 0.0, -0.0, 1.0, 0.1, 1e300, 5e-324, 2.5, 0.5, 1.5 })
  {
    EXPECT_EQ(generalText(x, 17), printed("%.17g", x));
    EXPECT_EQ(fixedText(x, 0), printed("%.0f", x)) << "rounding half to even, as printf";
  }
  EXPECT_EQ(cLocaleReal("1.5e-400"), 0.0);
  EXPECT_EQ(cLocaleReal("1e400"), HUGE_VAL);
  EXPECT_EQ(cLocaleReal("0.25"), 0.25);
}

TEST(NumberText, FilesMessagesAndReadingIgnoreTheLocale)
{
  const GermanNumbers german;
  // Where the sources are (Debian's locales package, which .ci installs), a
  // locale that cannot be made is a failure, not a skip.
  if (!german.ok() && fs::exists("/usr/share/i18n/locales/de_DE"))
    FAIL() << "localedef did not make a usable German locale from /usr/share/i18n";
  if (!german.ok())
    GTEST_SKIP() << "no German locale could be made (localedef and Debian's locales package)";
  EXPECT_EQ(formatNumber(1.5), "1.5");
  EXPECT_EQ(formatPoint({ 0.25, -1.75 }), "(0.25, -1.75)");
  EXPECT_EQ(roughNumber(0.123), "0.12");
  // Reading: a number that underflows is 0, not its digits before the point.
  std::istringstream poly("3 2 0 0\n1 0.25 1.5e-400\n2 1.75 0.5\n3 0.5 1.25\n0 0\n0\n");
  const PolyFile read = parsePoly(poly, "t.poly");
  ASSERT_TRUE(read.ok) << read.error;
  EXPECT_EQ(read.pslg.points[0].y, 0.0);
  EXPECT_EQ(read.pslg.points[0].x, 0.25);
  // Writing: every number of the .node, .ele, .poly, SVG and JSON with a point.
  const Result r = mesh(read.pslg);
  ASSERT_TRUE(r.ok) << r.error;
  const std::string base = (german.dir() / "out").string();
  NodeData data;
  data.holes = { { 0.75, 0.25 } };
  ASSERT_EQ(writeTriangleFiles(base, r, data), "");
  for (const char* extension : { ".node", ".poly" })
  {
    std::ifstream in(base + extension);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find(','), std::string::npos) << extension << ":\n" << text;
    EXPECT_NE(text.find("0.25"), std::string::npos) << extension << ":\n" << text;
  }
  const PolyFile again = readPolyFile(base + ".node");
  ASSERT_TRUE(again.ok) << again.error;
  EXPECT_EQ(again.pslg.points.size(), r.mesh.vertices.size());
  std::ostringstream svg, json;
  writeSvg(svg, r);
  writeStatisticsJson(json, r);
  EXPECT_NE(svg.str().find(".000\""), std::string::npos);
  EXPECT_EQ(svg.str().find(",000"), std::string::npos);
  EXPECT_NE(json.str().find("\"MaxAngleDeg\": "), std::string::npos);
  const std::size_t at = json.str().find("\"MaxAngleDeg\": ");
  EXPECT_EQ(json.str().find(',', at), json.str().find(",\n", at)) << json.str().substr(at, 60);
  // A message with a number: the angle beyond the guarantee.
  Options steep;
  steep.minAngleDeg = 30.5;
  const Result s = mesh(read.pslg, steep);
  bool said = false;
  for (const std::string& w : s.warnings)
    said = said || w.find("(here 30.5)") != std::string::npos;
  EXPECT_TRUE(said) << "the warning names 30.5 with a point";
}

} // namespace
} // namespace osm
