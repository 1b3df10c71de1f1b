#include "NumberText.h"

#include <charconv>
#include <clocale>
#include <cstdlib>

#if defined(__GLIBC__)
#include <locale.h>
#endif

namespace osm
{

namespace
{
std::string toText(double x, std::chars_format format, int precision)
{
  char buf[400]; // %.17g needs 24, %.3f of 1e308 about 313
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x, format, precision);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}
} // namespace

std::string generalText(double x, int digits)
{
  return toText(x, std::chars_format::general, digits);
}

std::string fixedText(double x, int decimals)
{
  return toText(x, std::chars_format::fixed, decimals);
}

double cLocaleReal(const std::string& text)
{
#if defined(__GLIBC__)
  static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  if (c)
    return strtod_l(text.c_str(), nullptr, c);
#endif
  return std::strtod(text.c_str(), nullptr);
}

} // namespace osm
