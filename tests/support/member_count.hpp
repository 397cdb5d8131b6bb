#pragma once
// The number of members of an aggregate, for the tests that check a field list names every
// member (segment_state.hpp, point_result.hpp): the largest count of arguments it can be brace-
// initialised from (each argument converts to any member type).
#include <cstddef>
#include <type_traits>
#include <utility>

namespace hmfnet::test {

struct AnyMember {
  template <class T>
  operator T&() const;  // never defined: used in unevaluated contexts only
};

template <class T, class Indices, class = void>
struct BraceConstructible : std::false_type {};
template <class T, std::size_t... I>
struct BraceConstructible<T, std::index_sequence<I...>,
                          std::void_t<decltype(T{(void(I), AnyMember{})...})>> : std::true_type {};

template <class T, std::size_t N = 0>
constexpr std::size_t member_count() {
  if constexpr (BraceConstructible<T, std::make_index_sequence<N + 1>>::value) {
    return member_count<T, N + 1>();
  } else {
    return N;
  }
}

}  // namespace hmfnet::test
