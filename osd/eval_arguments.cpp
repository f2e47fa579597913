#include "osd/internal/eval_arguments.h"

#include <stdexcept>
#include <string>

namespace quadtri {
inline namespace v0 {
namespace detail {

bool checkEvalArguments(bool srcPresent, const BufferDescriptor& srcDesc, bool dstPresent,
                        const BufferDescriptor& dstDesc, int numStencils, int start, int& end) {
    if (end < 0) end = numStencils;
    if (!srcDesc.isValid() || !dstDesc.isValid())
        throw std::invalid_argument("EvalStencils: invalid BufferDescriptor (need length > 0, stride >= length, offset >= 0)");
    if (srcDesc.length != dstDesc.length)
        throw std::invalid_argument("EvalStencils: source length " + std::to_string(srcDesc.length) +
                                    " differs from destination length " + std::to_string(dstDesc.length));
    if (start < 0 || start > end || end > numStencils)
        throw std::invalid_argument("EvalStencils: range [" + std::to_string(start) + ", " + std::to_string(end) +
                                    ") outside the table's " + std::to_string(numStencils) + " stencils");
    if (start == end) return false;
    if (!srcPresent || !dstPresent) throw std::invalid_argument("EvalStencils: null buffer");
    return true;
}

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
