// Numbers as text, whatever the host's locale: printf's %g and %f, and
// strtod, follow LC_NUMERIC, which a GUI host may set (Qt sets it from the
// environment), so that a German one wrote ".node" lines as "2 0,25 1,75 1"
// and read "1.5e-400" as 1 (a review). std::to_chars and std::from_chars do
// not look at the locale.
#ifndef osm_NumberText_h
#define osm_NumberText_h

#include <string>

namespace osm
{

/// x as printf's "%.{digits}g" writes it in the C locale.
std::string generalText(double x, int digits);

/// x as printf's "%.{decimals}f" writes it in the C locale.
std::string fixedText(double x, int decimals);

/// The text as strtod reads it in the C locale, up to its first character
/// that is not part of a number (0 if none is).
double cLocaleReal(const std::string& text);

} // namespace osm

#endif
