// skelconv/detail/unsigned_zero.hpp — +0 for a zero of either sign, every
// other double unchanged.
//
// The outputs (`skelconv eval`, `skelconv bound`, the Python module's field
// and bound) never show −0: an enclosure's lower end comes out of directed
// rounding as −0 at a box straddling a compact support, and a −0 reads as a
// negative value where the number is 0. A negative number however small
// (a subnormal −5e-324) keeps its sign: it is not 0.
#pragma once

namespace skelconv::detail {

constexpr double unsigned_zero(double x) { return x == 0.0 ? 0.0 : x; }

}  // namespace skelconv::detail
