// A fixed-size array that lives in memory someone else owns (an ArrayBlock): what a tire's
// per-particle and per-constraint arrays are. It reads like std::span (size, data, [], begin/end;
// it converts to std::span; assign() copies values in), with two differences that make it behave like the
// member array it replaces:
//  - const is deep: through a const ArrayView the elements are const, so a const Tire& still
//    cannot move a particle;
//  - it cannot be copied, only moved. `a = b` on a span silently makes a alias b's elements where
//    the code that used std::vector meant "copy the values" (std::copy says that); and a copy of
//    its holder would share the original's elements. Moving hands the elements over with the
//    block that holds them, which keeps its address: the view stays valid.
#pragma once

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <utility>

#include "tire/math/check.h"

namespace tire {

template <typename T>
class ArrayView {
 public:
  using value_type = T;
  using iterator = T*;
  using const_iterator = const T*;

  ArrayView() = default;
  // `size` elements from `data`; whoever calls this owns them and keeps them alive (ArrayBlock).
  ArrayView(T* data, std::size_t size) : data_(data), size_(size) {}
  ArrayView(ArrayView&& o) noexcept
      : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}
  ArrayView& operator=(ArrayView&& o) noexcept {
    data_ = std::exchange(o.data_, nullptr);
    size_ = std::exchange(o.size_, 0);
    return *this;
  }
  ArrayView(const ArrayView&) = delete;
  ArrayView& operator=(const ArrayView&) = delete;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  // Checked in debug builds, as _GLIBCXX_ASSERTIONS checks the std::vector this replaced.
  T& operator[](std::size_t i) {
    TIRE_ASSERT(i < size_, "an array index out of range");
    return data_[i];
  }
  const T& operator[](std::size_t i) const {
    TIRE_ASSERT(i < size_, "an array index out of range");
    return data_[i];
  }
  T& front() { return (*this)[0]; }
  const T& front() const { return (*this)[0]; }
  T& back() { return (*this)[size_ - 1]; }
  const T& back() const { return (*this)[size_ - 1]; }
  // Copies `values` in, one for each element (the size is fixed): what `v = values` was for the
  // std::vector this replaced.
  void assign(std::span<const T> values) {
    TIRE_ASSERT(values.size() == size_, "values for an array of another size");
    std::copy_n(values.begin(), std::min(values.size(), size_), data_);
  }
  void assign(std::initializer_list<T> values) { assign(std::span<const T>(values.begin(), values.size())); }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace tire
