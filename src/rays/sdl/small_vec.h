// SmallVec: a vector that keeps its first N elements inline, so the few arguments of a call or
// the by-reference parameters of a macro cost no heap allocation.
#pragma once
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace rays::sdl {

template <class T, size_t N>
class SmallVec {
public:
    void push_back(T v) {
        if (n_ < N) inline_[n_] = std::move(v);
        else spill_.push_back(std::move(v));
        ++n_;
    }
    template <class... A>
    void emplace_back(A&&... a) { push_back(T(std::forward<A>(a)...)); }
    size_t size() const { return n_; }
    bool empty() const { return n_ == 0; }
    T& operator[](size_t i) { return i < N ? inline_[i] : spill_[i - N]; }
    const T& operator[](size_t i) const { return i < N ? inline_[i] : spill_[i - N]; }
    const T& back() const { return (*this)[n_ - 1]; }

private:
    std::array<T, N> inline_{};
    std::vector<T> spill_;
    size_t n_ = 0;
};

}  // namespace rays::sdl
