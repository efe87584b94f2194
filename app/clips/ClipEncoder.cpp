#include "app/clips/ClipEncoder.h"

#include <QFileInfo>

#include <cmath>

namespace phasebox {

std::optional<ClipFormat> clipFormatOf(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("mp4")) return ClipFormat::Mp4;
    if (suffix == QLatin1String("gif")) return ClipFormat::Gif;
    return std::nullopt;
}

QString clipFormatList() {
    return QStringLiteral(".mp4 (H.264 video), .gif (animated GIF)");
}

QString clipSpecProblem(ClipFormat format, const ClipSpec& spec) {
    if (format == ClipFormat::Mp4 && (spec.size.width() % 2 || spec.size.height() % 2))
        return QStringLiteral(
                   "an MP4 (H.264) clip needs an even width and height (got %1x%2): its colour "
                   "is stored per 2x2 pixels")
            .arg(spec.size.width())
            .arg(spec.size.height());
    // A delay of 0 or 1 hundredth is shown as 10 by most browsers: the clip would crawl.
    if (format == ClipFormat::Gif && spec.fps > 50)
        return QStringLiteral(
                   "a GIF holds at most 50 frames per second (its delays are whole hundredths "
                   "of a second, and viewers slow down shorter ones); got %1")
            .arg(spec.fps);
    return {};
}

int gifDelayHundredths(const ClipSpec& spec, int frame) {
    const double total = std::round(100.0 * spec.seconds);
    const double n = std::max(1, spec.frames);
    return static_cast<int>(std::round((frame + 1) * total / n) - std::round(frame * total / n));
}

std::unique_ptr<ClipEncoder> openClipEncoder(ClipFormat format, const ClipSpec& spec,
                                             OutputFile& out, QString* error) {
    if (const QString problem = clipSpecProblem(format, spec); !problem.isEmpty()) {
        if (error) *error = problem;
        return nullptr;
    }
    return format == ClipFormat::Mp4 ? openMp4Encoder(spec, out, error)
                                     : openGifEncoder(spec, out, error);
}

}  // namespace phasebox
