// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One visitor made of several lambdas, for std::visit over a closed set of alternatives:
//
//     std::visit(Overloaded{[](const Circle& c) { ... }, [](const Polygon& p) { ... }}, v);
//
// A visitor that misses an alternative does not compile, so adding one lists every site
// that must handle it.

namespace rigidlab::physics {

template <class... Fs> struct Overloaded : Fs... {
    using Fs::operator()...;
};

template <class... Fs> Overloaded(Fs...) -> Overloaded<Fs...>;

} // namespace rigidlab::physics
