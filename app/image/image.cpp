// Size checks shared by the metrics and the diff helpers: both report user mistakes (a reference
// or mask of the wrong resolution) as InputError with the sizes involved.
#include "image/image.h"

#include "core/input_error.h"
#include "core/strings.h"

namespace ispm {

void requireSameSize(const Image& test, const Image& reference) {
    if (test.width != reference.width || test.height != reference.height) {
        throw InputError(strCat("expected images of the same size, got test ", test.width, "x",
                                test.height, " and reference ", reference.width, "x",
                                reference.height));
    }
}

Image subtractImages(const Image& a, const Image& b) {
    requireSameSize(a, b);
    Image out = a;
    for (size_t i = 0; i < out.pixels.size(); ++i)
        out.pixels[i] -= b.pixels[i];
    return out;
}

void requireMaskSize(const Image& image, const PixelMask* mask) {
    if (mask != nullptr && mask->size() != image.getPixelCount()) {
        throw InputError(strCat("expected a mask of ", image.width, "x", image.height, " = ",
                                image.getPixelCount(), " pixels, got ", mask->size()));
    }
}

} // namespace ispm
