#pragma once
// Reals that must survive a restart bit for bit (the time, the step, a solver's previous step),
// written into <time>/state as C99 hexadecimal text ("0x1.999999999999ap-4") and read back whole.
#include <string>

namespace mfdyn {

class Dictionary;

// x as hexadecimal text, exact.
std::string exactRealText(double x);

// The real written at `key` by exactRealText. strtod alone would take "", "nan", "inf" and
// trailing garbage, so each is an InputError at the entry ("the state file is damaged").
double readExactReal(const Dictionary& state, const std::string& key);

}  // namespace mfdyn
