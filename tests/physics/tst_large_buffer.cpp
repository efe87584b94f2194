// LargeVector (physics/core/LargeBuffer.h): the contact arrays' vector. Small buffers come from
// operator new with the element's alignment; from 2 MB on each buffer is its own mapping,
// aligned to a huge page and advised to the kernel as one (on Linux: the mapping's VmFlags in
// /proc/self/smaps carry "hg"). Growing, swapping and moving keep every element.

#include "physics/core/LargeBuffer.h"

#include <QFile>
#include <QTest>

#include <cstdint>
#include <utility>

using namespace phasebox;

namespace {

struct alignas(64) Lanes {
    double value[8];
};

bool aligned(const void* p, std::size_t alignment) {
    return reinterpret_cast<std::uintptr_t>(p) % alignment == 0;
}

// The VmFlags line of the mapping that holds p, or an empty string.
QByteArray flagsOfMappingAt(const void* p) {
    QFile smaps("/proc/self/smaps");
    if (!smaps.open(QIODevice::ReadOnly)) return {};
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    bool inside = false;
    // /proc files report no size: read them whole, not up to atEnd().
    const QList<QByteArray> lines = smaps.readAll().split('\n');
    for (const QByteArray& line : lines) {
        const int dash = line.indexOf('-'), space = line.indexOf(' ');
        if (dash > 0 && space > dash) {  // a mapping's first line: "start-end perms ..."
            bool okStart = false, okEnd = false;
            const auto start = line.left(dash).toULongLong(&okStart, 16);
            const auto end = line.mid(dash + 1, space - dash - 1).toULongLong(&okEnd, 16);
            if (okStart && okEnd) {
                inside = start <= at && at < end;
                continue;
            }
        }
        if (inside && line.startsWith("VmFlags:")) return line.trimmed();
    }
    return {};
}

}  // namespace

class TestLargeBuffer : public QObject {
    Q_OBJECT

private slots:
    void smallBuffersKeepTheElementsAlignment() {
        LargeVector<Lanes> lanes(3);
        QVERIFY(aligned(lanes.data(), alignof(Lanes)));
        LargeVector<double> values(100, 1.5);
        QCOMPARE(values[99], 1.5);
    }

    void largeBuffersStartOnAHugePage() {
        LargeVector<Lanes> lanes(large_buffer::kHugePage / sizeof(Lanes) + 1);
        QVERIFY(aligned(lanes.data(), large_buffer::kHugePage));
        lanes.back().value[7] = 2.0;  // the last byte of a buffer one element past 2 MB
        QCOMPARE(lanes.back().value[7], 2.0);
    }

    void growingAcrossTheThresholdKeepsEveryElement() {
        LargeVector<std::int64_t> values;
        const std::int64_t count = 3 * large_buffer::kHugePage / sizeof(std::int64_t);
        for (std::int64_t i = 0; i < count; ++i) values.push_back(i * 7);
        QVERIFY(aligned(values.data(), large_buffer::kHugePage));
        for (std::int64_t i = 0; i < count; ++i)
            if (values[i] != i * 7) QFAIL(qPrintable(QString("element %1 changed").arg(i)));
        values.resize(10);
        values.shrink_to_fit();  // back below the threshold: operator new again
        QCOMPARE(values.size(), std::size_t{10});
        QCOMPARE(values[9], std::int64_t{63});
    }

    void swappingAndMovingKeepTheBuffers() {
        LargeVector<double> large(large_buffer::kHugePage / sizeof(double), 3.0);
        LargeVector<double> small(4, 1.0);
        const double* buffer = large.data();
        std::swap(large, small);
        QCOMPARE(small.data(), buffer);
        QCOMPARE(large.size(), std::size_t{4});
        LargeVector<double> moved = std::move(small);
        QCOMPARE(moved.data(), buffer);
        QCOMPARE(moved.back(), 3.0);
    }

    // Linux: the kernel was asked for huge pages (VmFlags "hg"). Elsewhere there is no such
    // advice; what the buffer can give is its huge-page alignment, checked there instead.
    void largeBuffersAreAdvisedAsHugePages() {
        LargeVector<char> bytes(4 * large_buffer::kHugePage, 'x');
        QVERIFY(aligned(bytes.data(), large_buffer::kHugePage));
#if defined(__linux__)
        const QByteArray flags = flagsOfMappingAt(bytes.data() + bytes.size() / 2);
        QVERIFY2(!flags.isEmpty(), "no mapping in /proc/self/smaps holds the buffer");
        QVERIFY2(flags.split(' ').contains("hg"), flags.constData());
#endif
    }
};

QTEST_GUILESS_MAIN(TestLargeBuffer)
#include "tst_large_buffer.moc"
