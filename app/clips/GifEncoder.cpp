// Animated GIF through giflib: its median-cut quantiser (GifQuantizeBuffer) gives each frame its
// own 256-colour table, and its encoder writes the LZW data and the blocks. Only what changed
// since the previous frame is stored (the bounding box of the changed pixels, drawn over the
// frame before it), which for a few moving objects on a still background is a small fraction
// of the picture; a frame that changed nothing is one pixel, so every frame keeps its own delay
// and the clip has exactly the frames it was given.

#include "app/clips/ClipEncoder.h"
#include "app/io/OutputFile.h"

#include <QByteArray>
#include <QImage>
#include <QRect>

#include <gif_lib.h>

#include <vector>

namespace phasebox {

namespace {

class GifEncoder final : public ClipEncoder {
public:
    GifEncoder(const ClipSpec& spec, OutputFile& out) : spec_(spec), out_(out) {}
    ~GifEncoder() override {
        if (gif_) EGifCloseFile(gif_, nullptr);
    }

    bool open() {
        int code = 0;
        gif_ = EGifOpen(this, &GifEncoder::output, &code);
        if (!gif_) return fail(code);
        EGifSetGifVersion(gif_, true);  // GIF89a: delays and the loop need it
        if (EGifPutScreenDesc(gif_, spec_.size.width(), spec_.size.height(), 8, 0, nullptr) ==
            GIF_ERROR)
            return fail(gif_->Error);
        // The NETSCAPE2.0 application block: loop for ever, as a clip on a slide should.
        static const GifByteType kNetscape[] = "NETSCAPE2.0";
        static const GifByteType kLoopForever[] = {1, 0, 0};
        if (EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
            EGifPutExtensionBlock(gif_, 11, kNetscape) == GIF_ERROR ||
            EGifPutExtensionBlock(gif_, 3, kLoopForever) == GIF_ERROR ||
            EGifPutExtensionTrailer(gif_) == GIF_ERROR)
            return fail(gif_->Error);
        return true;
    }

    bool addFrame(const QImage& image) override {
        if (image.size() != spec_.size) {
            error_ = QStringLiteral("a frame of the wrong size was drawn");
            return false;
        }
        const QImage frame = image.convertToFormat(QImage::Format_RGB32);
        const QRect changed = changedArea(frame);
        GraphicsControlBlock control{};
        control.DisposalMode = DISPOSE_DO_NOT;  // the next frame is drawn over this one
        control.UserInputFlag = false;
        control.DelayTime = gifDelayHundredths(spec_, index_);
        control.TransparentColor = NO_TRANSPARENT_COLOR;
        GifByteType extension[4];
        const std::size_t length = EGifGCBToExtension(&control, extension);
        if (EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension) ==
            GIF_ERROR)
            return fail(gif_->Error);
        if (!putImage(frame, changed)) return false;
        previous_ = frame;
        ++index_;
        return true;
    }

    bool finish() override {
        int code = 0;
        GifFileType* gif = gif_;
        gif_ = nullptr;
        if (EGifCloseFile(gif, &code) == GIF_ERROR) return fail(code);
        return true;
    }

private:
    static int output(GifFileType* gif, const GifByteType* data, int size) {
        auto* self = static_cast<GifEncoder*>(gif->UserData);
        if (!self->out_.write(QByteArray(reinterpret_cast<const char*>(data), size))) return 0;
        return size;
    }

    // The output's message when the bytes could not be written, else giflib's.
    bool fail(int code) {
        if (error_.isEmpty())
            error_ = out_.failed() ? out_.error()
                                   : out_.path() + QStringLiteral(": cannot write the GIF: ") +
                                         QString::fromUtf8(GifErrorString(code));
        return false;
    }

    // The bounding box of the pixels that differ from the previous frame (all of the first
    // frame; one pixel when nothing changed).
    QRect changedArea(const QImage& frame) const {
        if (previous_.isNull()) return frame.rect();
        int top = frame.height(), bottom = -1, left = frame.width(), right = -1;
        for (int y = 0; y < frame.height(); ++y) {
            const auto* a = reinterpret_cast<const QRgb*>(frame.constScanLine(y));
            const auto* b = reinterpret_cast<const QRgb*>(previous_.constScanLine(y));
            int x0 = 0;
            while (x0 < frame.width() && a[x0] == b[x0]) ++x0;
            if (x0 == frame.width()) continue;
            int x1 = frame.width() - 1;
            while (a[x1] == b[x1]) --x1;
            top = std::min(top, y);
            bottom = y;
            left = std::min(left, x0);
            right = std::max(right, x1);
        }
        if (bottom < 0) return QRect(0, 0, 1, 1);
        return QRect(QPoint(left, top), QPoint(right, bottom));
    }

    // The pixels of area, quantised to their own 256 colours, as one GIF image.
    bool putImage(const QImage& frame, const QRect& area) {
        const int w = area.width(), h = area.height();
        const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
        red_.resize(n);
        green_.resize(n);
        blue_.resize(n);
        indices_.resize(n);
        std::size_t k = 0;
        for (int y = area.top(); y <= area.bottom(); ++y) {
            const auto* row = reinterpret_cast<const QRgb*>(frame.constScanLine(y));
            for (int x = area.left(); x <= area.right(); ++x, ++k) {
                red_[k] = static_cast<GifByteType>(qRed(row[x]));
                green_[k] = static_cast<GifByteType>(qGreen(row[x]));
                blue_[k] = static_cast<GifByteType>(qBlue(row[x]));
            }
        }
        int colours = 256;
        GifColorType palette[256] = {};
        if (GifQuantizeBuffer(static_cast<unsigned>(w), static_cast<unsigned>(h), &colours,
                              red_.data(), green_.data(), blue_.data(), indices_.data(),
                              palette) == GIF_ERROR) {
            error_ = QStringLiteral("cannot reduce a frame to 256 colours");
            return false;
        }
        ColorMapObject* map = GifMakeMapObject(256, palette);
        if (!map) {
            error_ = QStringLiteral("out of memory");
            return false;
        }
        const bool described =
            EGifPutImageDesc(gif_, area.left(), area.top(), w, h, false, map) != GIF_ERROR;
        GifFreeMapObject(map);
        if (!described) return fail(gif_->Error);
        for (int y = 0; y < h; ++y)
            if (EGifPutLine(gif_, indices_.data() + static_cast<std::size_t>(y) * w, w) ==
                GIF_ERROR)
                return fail(gif_->Error);
        return true;
    }

    ClipSpec spec_;
    OutputFile& out_;
    GifFileType* gif_ = nullptr;
    QImage previous_;
    int index_ = 0;
    std::vector<GifByteType> red_, green_, blue_, indices_;
};

}  // namespace

std::unique_ptr<ClipEncoder> openGifEncoder(const ClipSpec& spec, OutputFile& out, QString* error) {
    auto encoder = std::make_unique<GifEncoder>(spec, out);
    if (encoder->open()) return encoder;
    if (error) *error = encoder->error();
    return nullptr;
}

}  // namespace phasebox
