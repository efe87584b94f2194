#pragma once
// Clips for slides (CONTRACT.md §8): H.264 in MP4 through libavcodec and libavformat, animated
// GIF through giflib. No encoder is written here; this layer only feeds the libraries frames
// and hands their bytes to OutputFile, the one writer of every file, so a clip that fails or is
// cancelled leaves no partial file and an earlier file of that name whole.

#include <QSize>
#include <QString>

#include <memory>
#include <optional>

QT_BEGIN_NAMESPACE
class QImage;
QT_END_NAMESPACE

namespace phasebox {

class OutputFile;

enum class ClipFormat { Mp4, Gif };

// The format a file name asks for by its extension (.mp4 or .gif, any case), or nothing.
std::optional<ClipFormat> clipFormatOf(const QString& path);
// The formats for a message: ".mp4 (H.264 video), .gif (animated GIF)".
QString clipFormatList();

struct ClipSpec {
    QSize size;          // of every frame, in pixels
    int fps = 30;        // frames per second
    int frames = 0;      // how many frames will be given
    double seconds = 0;  // the clip's length: a GIF's delays add up to it within 1/100 s
};

// Why spec cannot be encoded in format (an odd size for H.264's 4:2:0 colour, a GIF frame
// shorter than a hundredth of a second), or an empty string.
QString clipSpecProblem(ClipFormat format, const ClipSpec& spec);

// A GIF's delays in hundredths of a second: frame k (of spec.frames) lasts
// round((k+1)·T/N) − round(k·T/N) with T = round(100·seconds), so the delays alternate
// (3, 4, 3, 3, 4, 3, … at 30 fps) and add up to T exactly.
int gifDelayHundredths(const ClipSpec& spec, int frame);

class ClipEncoder {
public:
    virtual ~ClipEncoder() = default;
    // Encodes the next frame (any QImage format; its size must be spec.size).
    virtual bool addFrame(const QImage& frame) = 0;
    // Ends the stream and hands the last bytes to the output. The output is not committed.
    virtual bool finish() = 0;
    // What failed: the output's own message, or the library's.
    const QString& error() const { return error_; }

protected:
    QString error_;
};

// An encoder that writes to out (opened by the caller, committed or cancelled by the caller).
// nullptr with *error set when the library refuses the format.
std::unique_ptr<ClipEncoder> openClipEncoder(ClipFormat format, const ClipSpec& spec,
                                             OutputFile& out, QString* error);

// One per format, in their own files.
std::unique_ptr<ClipEncoder> openMp4Encoder(const ClipSpec& spec, OutputFile& out, QString* error);
std::unique_ptr<ClipEncoder> openGifEncoder(const ClipSpec& spec, OutputFile& out, QString* error);

}  // namespace phasebox
