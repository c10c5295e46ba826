#include "tire/math/array_block.h"

namespace tire {

ArrayBlock::ArrayBlock(const BlockLayout& layout) : size_(layout.size()), alignment_(layout.alignment()) {
  if (size_ > 0) bytes_ = static_cast<std::byte*>(::operator new (size_, std::align_val_t{alignment_}));
}

ArrayBlock::~ArrayBlock() { release(); }

ArrayBlock& ArrayBlock::operator=(ArrayBlock&& o) noexcept {
  if (this != &o) {
    release();
    bytes_ = std::exchange(o.bytes_, nullptr);
    size_ = std::exchange(o.size_, 0);
    alignment_ = std::exchange(o.alignment_, BlockLayout::kCacheLine);
  }
  return *this;
}

void ArrayBlock::release() noexcept {
  if (bytes_) ::operator delete (bytes_, size_, std::align_val_t{alignment_});
  bytes_ = nullptr;
  size_ = 0;
}

}  // namespace tire
