// Where per-vertex data lives in a float buffer: element i occupies
// [offset + i*stride, offset + i*stride + length).
#pragma once

namespace quadtri {
inline namespace v0 {

struct BufferDescriptor {
    int offset = 0;  // floats before element 0
    int length = 0;  // floats evaluated per element
    int stride = 0;  // floats between consecutive elements (>= length)

    BufferDescriptor() = default;
    BufferDescriptor(int offset_, int length_, int stride_) : offset(offset_), length(length_), stride(stride_) {}
    bool isValid() const { return length > 0 && stride >= length && offset >= 0; }
};

}  // namespace v0
}  // namespace quadtri
