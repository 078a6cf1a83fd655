#pragma once
// A vector with inline storage for the common case: span lists per ray per
// node are short (a torus gives at most two spans), and allocating on every
// ray would dominate the per-pixel cost.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>

namespace lattice {

template <typename E, std::size_t N>
class SmallVector {
  static_assert(std::is_trivially_copyable_v<E>, "SmallVector holds plain data");

 public:
  SmallVector() = default;
  SmallVector(const SmallVector& o) { assign(o); }
  SmallVector& operator=(const SmallVector& o) {
    if (this != &o) {
      size_ = 0;
      assign(o);
    }
    return *this;
  }
  ~SmallVector() = default;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() { size_ = 0; }
  E* begin() { return data(); }
  E* end() { return data() + size_; }
  const E* begin() const { return data(); }
  const E* end() const { return data() + size_; }
  E& operator[](std::size_t i) { return data()[i]; }
  const E& operator[](std::size_t i) const { return data()[i]; }
  E& back() { return data()[size_ - 1]; }
  const E& back() const { return data()[size_ - 1]; }

  void push_back(const E& e) {
    if (size_ == capacity_) grow(capacity_ * 2);
    data()[size_++] = e;
  }
  void pop_back() { --size_; }

 private:
  E* data() { return heap_ ? heap_.get() : inline_; }
  const E* data() const { return heap_ ? heap_.get() : inline_; }
  void grow(std::size_t capacity) {
    auto bigger = std::make_unique<E[]>(capacity);
    std::copy(data(), data() + size_, bigger.get());
    heap_ = std::move(bigger);
    capacity_ = capacity;
  }
  void assign(const SmallVector& o) {
    if (o.size_ > capacity_) grow(o.size_);
    std::copy(o.data(), o.data() + o.size_, data());
    size_ = o.size_;
  }

  E inline_[N]{};
  std::unique_ptr<E[]> heap_;
  std::size_t size_ = 0;
  std::size_t capacity_ = N;
};

}  // namespace lattice
