#include "physics/contacts/ContactSolver.h"

#include "physics/contacts/ContactChunks.h"
#include "physics/contacts/ContactImpulse.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define PHASEBOX_WIDE_CONTACTS 1
#include <immintrin.h>
#endif

namespace phasebox {

using namespace contact_impulse;

namespace {
using WideRow = ContactSolver::WideRow;
using WideCold = ContactSolver::WideCold;
using WideClosing = ContactSolver::WideClosing;
using ContactSolverBody = ContactSolver::BodyState;
using RowSetup = ContactSolver::RowSetup;
using WideSetup = ContactSolver::WideSetup;
using BodyMotion = ContactSolver::BodyMotion;
using PhaseTerms = ContactSolver::PhaseTerms;

// The wide kernels load a body's state and motion four doubles at a time (gatherFour).
static_assert(offsetof(ContactSolverBody, w) == 2 * sizeof(double) &&
              offsetof(ContactSolverBody, invMass) == 3 * sizeof(double));
static_assert(offsetof(BodyMotion, sin) == 3 * sizeof(double) && sizeof(BodyMotion) == 32);

// The wide sweep where AVX2 is there (chosen at run time; the build is generic x86-64), on
// AVX-512 where that is there too. No fused multiply-add: each lane does the scalar row's
// operations (solveRow) in the same order, so every instruction set gives the same bits.
constexpr int kLanes = ContactSolver::kLanes;
#ifdef PHASEBOX_WIDE_CONTACTS
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
// Four lanes at a time: GCC's eight-lane vectors split in two on AVX2 were 1.7 times slower.
constexpr int kWidth = 4;
typedef double Lanes __attribute__((vector_size(8 * kWidth)));
typedef long long Mask __attribute__((vector_size(8 * kWidth)));
// The first four doubles of a part's items (body states, body motions), each item in one load,
// turned into four lanes.
template <class Item>
inline void gatherFour(const Item* items, const int* index, Lanes& f0, Lanes& f1, Lanes& f2,
                       Lanes& f3) {
    const __m256d b0 = _mm256_loadu_pd(reinterpret_cast<const double*>(&items[index[0]]));
    const __m256d b1 = _mm256_loadu_pd(reinterpret_cast<const double*>(&items[index[1]]));
    const __m256d b2 = _mm256_loadu_pd(reinterpret_cast<const double*>(&items[index[2]]));
    const __m256d b3 = _mm256_loadu_pd(reinterpret_cast<const double*>(&items[index[3]]));
    const __m256d t01 = _mm256_unpacklo_pd(b0, b1), t23 = _mm256_unpacklo_pd(b2, b3);
    const __m256d u01 = _mm256_unpackhi_pd(b0, b1), u23 = _mm256_unpackhi_pd(b2, b3);
    f0 = Lanes(_mm256_permute2f128_pd(t01, t23, 0x20));
    f1 = Lanes(_mm256_permute2f128_pd(u01, u23, 0x20));
    f2 = Lanes(_mm256_permute2f128_pd(t01, t23, 0x31));
    f3 = Lanes(_mm256_permute2f128_pd(u01, u23, 0x31));
}
// Whether any lane of m is set, in one test instead of a lane-by-lane reduction.
inline bool someLane(const Mask& m) {
    return !_mm256_testz_si256(__m256i(m), __m256i(m));
}
// The lanes back into their bodies' states, gatherFour's shuffles undone: each body's four
// doubles (its inverse mass as it was) in one store, none to the static world (which other
// workers' rows of the same colour share), as the AVX-512 kernel does.
inline void scatterVelocities(ContactSolverBody* state, const int* index, int world,
                              const Lanes& vx, const Lanes& vy, const Lanes& w, const Lanes& m) {
    const __m256d t01 = _mm256_permute2f128_pd(__m256d(vx), __m256d(w), 0x20);
    const __m256d t23 = _mm256_permute2f128_pd(__m256d(vx), __m256d(w), 0x31);
    const __m256d u01 = _mm256_permute2f128_pd(__m256d(vy), __m256d(m), 0x20);
    const __m256d u23 = _mm256_permute2f128_pd(__m256d(vy), __m256d(m), 0x31);
    const __m256d body[4] = {_mm256_unpacklo_pd(t01, u01), _mm256_unpackhi_pd(t01, u01),
                             _mm256_unpacklo_pd(t23, u23), _mm256_unpackhi_pd(t23, u23)};
    for (int l = 0; l < kWidth; ++l)
        if (index[l] != world) _mm256_storeu_pd(&state[index[l]].vx, body[l]);
}
#include "physics/contacts/ContactWideLoop.inc"
}  // namespace avx2
#pragma GCC pop_options
#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512vl")
// AVX-512 brings fused multiply-add, which GCC would otherwise contract a·b + c into.
#pragma GCC optimize("fp-contract=off")
namespace avx512 {
constexpr int kWidth = kLanes;
typedef double Lanes __attribute__((vector_size(8 * kWidth)));
typedef long long Mask __attribute__((vector_size(8 * kWidth)));
// The first four doubles of eight items (body states, body motions): each item in one load, two
// items to a register, the eight turned into four lanes by two rounds of shuffles instead of 32
// single loads. (GCC's shuffles rather than the intrinsics, whose undefined pass-through GCC 12
// warns of.)
typedef double Quad __attribute__((vector_size(32)));
template <class Item>
inline void gatherFour(const Item* items, const int* index, Lanes& f0, Lanes& f1, Lanes& f2,
                       Lanes& f3) {
    Lanes pair[4];  // items 2j and 2j + 1: f0 f1 f2 f3 | f0 f1 f2 f3
    for (int j = 0; j < 4; ++j) {
        Quad first, second;
        __builtin_memcpy(&first, &items[index[2 * j]], sizeof first);
        __builtin_memcpy(&second, &items[index[2 * j + 1]], sizeof second);
        pair[j] = __builtin_shufflevector(first, second, 0, 1, 2, 3, 4, 5, 6, 7);
    }
    // f0 of items 0 2 | f2 of 0 2 | f0 of 1 3 | f2 of 1 3 (and items 4 to 7); likewise f1, f3.
    const Lanes even0 = __builtin_shufflevector(pair[0], pair[1], 0, 8, 2, 10, 4, 12, 6, 14);
    const Lanes even1 = __builtin_shufflevector(pair[2], pair[3], 0, 8, 2, 10, 4, 12, 6, 14);
    const Lanes odd0 = __builtin_shufflevector(pair[0], pair[1], 1, 9, 3, 11, 5, 13, 7, 15);
    const Lanes odd1 = __builtin_shufflevector(pair[2], pair[3], 1, 9, 3, 11, 5, 13, 7, 15);
    f0 = __builtin_shufflevector(even0, even1, 0, 4, 1, 5, 8, 12, 9, 13);
    f2 = __builtin_shufflevector(even0, even1, 2, 6, 3, 7, 10, 14, 11, 15);
    f1 = __builtin_shufflevector(odd0, odd1, 0, 4, 1, 5, 8, 12, 9, 13);
    f3 = __builtin_shufflevector(odd0, odd1, 2, 6, 3, 7, 10, 14, 11, 15);
}
// Whether any lane of m is set, in one test instead of a lane-by-lane reduction.
inline bool someLane(const Mask& m) {
    return _mm512_test_epi64_mask(__m512i(m), __m512i(m)) != 0;
}
// The lanes back into their bodies' states, the shuffles undone: each body's four doubles (its
// inverse mass as it was) in one store, none to the static world (which other workers' rows of
// the same colour share). The next colour loads the same four doubles: with masked stores of
// three the 20-row pyramid's step took 0.229 ms, with whole ones 0.223 ms (alternated runs).
inline void scatterVelocities(ContactSolverBody* state, const int* index, int world,
                              const Lanes& vx, const Lanes& vy, const Lanes& w, const Lanes& m) {
    const Lanes xw0 = __builtin_shufflevector(vx, w, 0, 2, 8, 10, 1, 3, 9, 11);
    const Lanes xw1 = __builtin_shufflevector(vx, w, 4, 6, 12, 14, 5, 7, 13, 15);
    const Lanes ym0 = __builtin_shufflevector(vy, m, 0, 2, 8, 10, 1, 3, 9, 11);
    const Lanes ym1 = __builtin_shufflevector(vy, m, 4, 6, 12, 14, 5, 7, 13, 15);
    // xw0: vx0 vx2 w0 w2 vx1 vx3 w1 w3; ym0 likewise with vy, m.
    Lanes pair[4];  // bodies 2j and 2j + 1: vx vy w m | vx vy w m
    pair[0] = __builtin_shufflevector(xw0, ym0, 0, 8, 2, 10, 4, 12, 6, 14);
    pair[1] = __builtin_shufflevector(xw0, ym0, 1, 9, 3, 11, 5, 13, 7, 15);
    pair[2] = __builtin_shufflevector(xw1, ym1, 0, 8, 2, 10, 4, 12, 6, 14);
    pair[3] = __builtin_shufflevector(xw1, ym1, 1, 9, 3, 11, 5, 13, 7, 15);
    for (int j = 0; j < 4; ++j) {
        const int first = index[2 * j], second = index[2 * j + 1];
        const Quad low = __builtin_shufflevector(pair[j], pair[j], 0, 1, 2, 3);
        const Quad high = __builtin_shufflevector(pair[j], pair[j], 4, 5, 6, 7);
        if (first != world) __builtin_memcpy(&state[first].vx, &low, sizeof low);
        if (second != world) __builtin_memcpy(&state[second].vx, &high, sizeof high);
    }
}
#include "physics/contacts/ContactWideLoop.inc"
}  // namespace avx512
#pragma GCC pop_options
#endif

using WideLoop = void (*)(WideRow*, const unsigned char*, int, ContactSolverBody*, int);
using WideWarm = void (*)(WideRow*, const WideCold*, const unsigned char*, int, ContactSolverBody*,
                          int);
using WideMeasure = void (*)(const WideRow*, WideCold*, const unsigned char*, int,
                             const BodyMotion*);
using WidePrepare = void (*)(WideRow*, WideCold*, const unsigned char*, int, const WideSetup*,
                             const BodyMotion*, const PhaseTerms&, unsigned char*, WideClosing*);
// The instruction set the wide kernels use: 2 AVX-512, 1 AVX2, 0 none. Without AVX2 the rows are
// solved one by one in the same colour order (the portable build of the wide loop, on SSE2
// pairs, was slower than that).
int wideLevel() {
#ifdef PHASEBOX_WIDE_CONTACTS
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx512vl"))
        return 2;
    if (__builtin_cpu_supports("avx2")) return 1;
#endif
    return 0;
}
// The kernels in use (all null: the rows one by one); ContactSolver::useInstructions() sets them.
struct WideKernels {
    int level = 0;  // wideLevel()'s scale
    WideLoop solve = nullptr;
    WideWarm warm = nullptr;
    WideMeasure measure = nullptr;
    WidePrepare prepare = nullptr;
};
WideKernels kernelsFor(int level) {
#ifdef PHASEBOX_WIDE_CONTACTS
    if (level >= 2)
        return {2, avx512::solveWideLoop, avx512::warmWideLoop, avx512::measureWideLoop,
                avx512::prepareWideLoop};
    if (level == 1)
        return {1, avx2::solveWideLoop, avx2::warmWideLoop, avx2::measureWideLoop,
                avx2::prepareWideLoop};
#endif
    (void)level;
    return {};
}
// PHASEBOX_CONTACT_INSTRUCTIONS (0, 1 or 2) caps the level, for benchmarks.
int startLevel() {
    const char* cap = std::getenv("PHASEBOX_CONTACT_INSTRUCTIONS");
    const int best = wideLevel();
    return cap && *cap >= '0' && *cap <= '2' && cap[1] == 0 ? std::min(best, *cap - '0') : best;
}
WideKernels wide = kernelsFor(startLevel());
}  // namespace

int ContactSolver::instructions() {
    return wide.level;
}

bool ContactSolver::useInstructions(int level) {
    if (level < 0 || level > wideLevel()) return false;
    wide = kernelsFor(level);
    return true;
}

void ContactSolver::loadBodies(const Vec& q0, const Vec& u0, const Vec& u) {
    const std::size_t count = bodies_.size();
    state_.resize(count + 1);
    motion_.resize(count + 1);
    deepShift_.resize(count + 1);  // sized here: a first deep overlap must not allocate
    state_[count] = {0.0, 0.0, 0.0, 0.0, 0.0};  // the static world
    motion_[count] = {0.0, 0.0, 1.0, 0.0};
    forChunks(count, kBodyGrain, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) {
            SolverBody& b = bodies_[i];
            b.v0 = u0.segment<2>(b.dof);
            b.smoothDv = u.segment<2>(b.dof) - b.v0;
            b.startOffset = q0.segment<2>(b.dof) - b.collidePosition;
            b.shift = b.path = b.timeShift = b.pushOut = b.bounceDv = b.impactDv = Vec2::Zero();
            b.angleShift = b.anglePath = b.angleTimeShift = b.pushOutAngle = b.bounceDw =
                b.impactDw = 0.0;
            if (b.rotates) {
                b.w0 = u0[b.dof + 2];
                b.smoothDw = u[b.dof + 2] - b.w0;
                b.startAngle = q0[b.dof + 2] - b.collideAngle;
            }
            state_[i] = {b.v0.x(), b.v0.y(), b.w0, b.invMass, b.invInertia};
        }
    });
}

void ContactSolver::reserve(std::size_t bodies, std::size_t constraints) {
    jammed_.clear();  // the bodies are bound anew: no count runs on across it
    bodies_.reserve(bodies);
    constraints_.reserve(constraints);
    state_.reserve(bodies + 1);
    motion_.reserve(bodies + 1);
    deepShift_.reserve(bodies + 1);
    changedAt_.reserve(bodies + 1);
    for (auto* perBody : {&depth_, &height_, &load_}) perBody->reserve(bodies + 1);
    supportStart_.reserve(bodies + 2);
    supportsUnder_.reserve(bodies + 1);
    supportReady_.reserve(bodies + 1);
    supportOrder_.reserve(constraints);
    rows_.reserve(constraints);
    setup_.reserve(constraints);
    slot_.reserve(constraints);
    colouredPairs_.reserve(constraints);
    bounceAt_.reserve(constraints);
    overflow_.reserve(constraints);
    bouncing_.reserve(constraints);
    bounceTerms_.reserve(constraints);
    handedOn_.reserve(constraints);
    handedTerms_.reserve(constraints);
    handedMade_.reserve(constraints);
    fastHanded_.reserve(constraints);
    support_.reserve(bodies + 1);
    supports_.reserve(constraints);
    for (auto* perPoint : {&shifted_, &bounces_}) perPoint->reserve(2 * constraints);
    separation_.reserve(2 * constraints);
    gathered_.reserve(2 * constraints);
    deep_.reserve(constraints);
    // Each colour's last wide row may be partly empty.
    wide_.reserve(constraints / kLanes + kColours);
    wideCold_.reserve(constraints / kLanes + kColours);
    wideClosing_.reserve(constraints / kLanes + kColours);
    closingWide_.reserve(constraints / kLanes + kColours);
    singleWide_.reserve(constraints / kLanes + kColours);
    laneKey_.reserve(constraints + kLanes * kColours);
    wideSetup_.reserve(constraints / kLanes + kColours);
    order_.reserve(constraints + kLanes * kColours);
    colourMask_.reserve(bodies + 1);
    colourWide_.reserve(kColours + 1);
    blockCount_.reserve(static_cast<std::size_t>(kColours) * kBlocks);
    blockWide_.reserve(static_cast<std::size_t>(kColours) * (kBlocks + 1));
}

void ContactSolver::preparePhase(double h, bool useBias, const ContactSettings& settings,
                                 bool measure) {
    // Per point: the bias velocity and the soft parameters (a speculative point, or a
    // penetrating one during relax, is rigid); per row the block's inverse. Separations are
    // fixed within a phase, so this is done once for all its iterations.
    const PhaseTerms terms{1.0 / h, settings.pushOut, useBias};
    if (lanesHold_) {
        forColours([&](std::size_t first, std::size_t end) {
            wide.prepare(wide_.data() + first, wideCold_.data() + first, singleWide_.data() + first,
                         static_cast<int>(end - first), wideSetup_.data() + first,
                         measure ? motion_.data() : nullptr, terms, closingWide_.data() + first,
                         wideClosing_.data() + first);
        });
        for (const int i : overflow_) prepareRow(static_cast<std::size_t>(i), terms, measure);
        return;
    }
    forChunks(rows_.size(), kRowGrain, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) prepareRow(i, terms, measure);
    });
}

void ContactSolver::prepareRow(std::size_t i, const PhaseTerms& terms, bool measure) {
    if (measure) rowSeparations(i);
    Row& c = rows_[i];
    const RowSetup& setup = setup_[i];
    double compliance[2] = {0.0, 0.0};
    bool active[2] = {true, true};
    for (int k = 0; k < c.pointCount; ++k) {
        RowPoint& p = c.p[k];
        const PointTerms t = pointTerms(separation_[2 * i + k], setup, k, terms);
        if (!terms.useBias) {
            // As the lanes do (ContactWideLoop.inc): speculative in the soft solve (its impulse
            // scale 0), touching now.
            p.closing = t.active && p.impulseScale == 0.0;
            p.relaxStartNormal = p.normalImpulse;
            p.relaxStartTangent = p.tangentImpulse;
        }
        active[k] = t.active;
        compliance[k] = t.compliance;
        p.bias = t.bias;
        p.effectiveMass = t.effectiveMass;
        p.impulseScale = t.impulseScale;
    }
    c.block = setup.blockable && active[0] && active[1];
    if (c.block) {
        const BlockTerms b = blockTerms(c.k11, c.k12, c.k22, compliance);
        c.a12 = b.a12;
        c.i11 = b.i11;
        c.i12 = b.i12;
        c.i22 = b.i22;
        c.invA11 = b.invA11;
        c.invA22 = b.invA22;
    }
}

void ContactSolver::bookClosing(int a, int b, double nx, double ny, const double (&arm)[4],
                                double normal, double tangent) {
    // The impulse's velocity change on each dynamic body (the static world's stays still).
    const int world = static_cast<int>(bodies_.size());
    const Vec2 impulse = normal * Vec2(nx, ny) + tangent * Vec2(ny, -nx);
    const auto book = [&](int index, bool onB) {
        SolverBody& body = bodies_[index];
        BodyState change{0.0, 0.0, 0.0, body.invMass, body.invInertia};
        if (onB)
            applyImpulse(change, arm[2], arm[3], impulse.x(), impulse.y());
        else
            removeImpulse(change, arm[0], arm[1], impulse.x(), impulse.y());
        body.impactDv += Vec2(change.vx, change.vy);
        body.impactDw += change.w;
    };
    if (a != world) book(a, false);
    if (b != world) book(b, true);
}

void ContactSolver::bookClosings() {
    // Serially, in the rows' order: a few rows in a sub-step, where bodies land.
    if (lanesHold_) {
        for (std::size_t r = 0; r < closingWide_.size(); ++r) {
            if (!closingWide_[r]) continue;
            const WideRow& w = wide_[r];
            const WideCold& u = wideCold_[r];
            const WideClosing& c = wideClosing_[r];
            for (int l = 0; l < kLanes; ++l)
                for (int k = 0; k < 2; ++k) {
                    if (!c.mask[k][l]) continue;
                    const WideCold::Point& e = u.p[k];
                    const double arm[4] = {e.rAx[l], e.rAy[l], e.rBx[l], e.rBy[l]};
                    bookClosing(w.a[l], w.b[l], w.nx[l], w.ny[l], arm,
                                w.p[k].normalImpulse[l] - c.normal[k][l],
                                w.p[k].tangentImpulse[l] - c.tangent[k][l]);
                }
        }
    }
    const auto bookRow = [&](const Row& row) {
        for (int k = 0; k < row.pointCount; ++k) {
            const RowPoint& p = row.p[k];
            if (!p.closing) continue;
            const double arm[4] = {p.rAx, p.rAy, p.rBx, p.rBy};
            bookClosing(row.a, row.b, row.nx, row.ny, arm, p.normalImpulse - p.relaxStartNormal,
                        p.tangentImpulse - p.relaxStartTangent);
        }
    };
    if (lanesHold_) {
        for (const int i : overflow_) bookRow(rows_[static_cast<std::size_t>(i)]);
    } else {
        for (const Row& row : rows_) bookRow(row);
    }
}

namespace {
// cos and sin of the turn since the contacts were found: a fraction of a step's rotation, so
// almost always small. Below 1/4 rad the Taylor polynomials (to x⁹ and x¹⁰) are within 3e-14 of
// the library's values, at a tenth of the cost (a libm call per body and phase was 5% of a
// pyramid's solve). Their nine divisions are independent of one another: two at a time, they
// give the same bits as one by one and no longer queue for the divider (they were most of
// updateMotion's time).
inline void smallRotation(double x, double& c, double& s) {
    if (!(std::abs(x) < 0.25)) {
        c = std::cos(x);
        s = std::sin(x);
        return;
    }
    // Two lanes: a register on every x86-64 (a wider vector is assembled through memory in the
    // default target, and its halves wait on the stores).
    using Pair = double __attribute__((vector_size(16)));
    const double x2 = x * x;
    const Pair square = {x2, x2};
    const Pair sin12 = square / Pair{6.0, 20.0}, sin34 = square / Pair{42.0, 72.0};
    const Pair cos12 = square / Pair{2.0, 12.0}, cos34 = square / Pair{30.0, 56.0};
    s = x * (1.0 - sin12[0] * (1.0 - sin12[1] * (1.0 - sin34[0] * (1.0 - sin34[1]))));
    c = 1.0 - cos12[0] * (1.0 - cos12[1] * (1.0 - cos34[0] * (1.0 - cos34[1] * (1.0 - x2 / 90.0))));
}
}  // namespace

inline void ContactSolver::endSolve(SolverBody& b, const BodyState& s, const SolveEnd& end) {
    const Vec2 v(s.vx, s.vy);
    // Contact-induced velocity, bounces included: what the impulses added to the smooth path,
    // which the integrator's positions do not know of.
    b.shift += end.h * (v - (b.v0 + end.f * b.smoothDv));
    b.path += end.h * v;
    if (b.rotates) {
        b.angleShift += end.h * (s.w - (b.w0 + end.f * b.smoothDw));
        b.anglePath += end.h * s.w;
    }
    b.pushV = v;
    b.pushW = s.w;
}

void ContactSolver::updateMotion(const SolveEnd* end) {
    // Bodies hold still while the solver iterates (positions move once per inner sub-step), so
    // each point's separation is computed once per phase, not once per iteration: the rotations
    // alone (a sine and a cosine per body and point) were a quarter of the solver's time.
    forChunks(bodies_.size(), kBodyGrain, [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
            SolverBody& b = bodies_[i];
            if (end) endSolve(b, state_[i], *end);
            const Vec2 dp = b.startOffset + b.path + b.timeShift;
            BodyMotion& m = motion_[i];
            m.dx = dp.x();
            m.dy = dp.y();
            // A disk's separations move with its centre alone: taken as a point of its rim,
            // the contact under a wheel that turns by Δθ would rise by r·(1 − cos Δθ) (2 mm in a
            // frame of a 0.25 m wheel at 2 m/s), the solver would let the wheel fall, and the
            // held force under it would be taken back every step.
            if (b.rotates && !b.round) {
                smallRotation(b.startAngle + b.anglePath + b.angleTimeShift, m.cos, m.sin);
            } else {
                m.cos = 1.0;
                m.sin = 0.0;
            }
        }
    });
}

void ContactSolver::rowSeparations(std::size_t i) {
    const Row& c = rows_[i];
    const BodyMotion& a = motion_[c.a];
    const BodyMotion& b = motion_[c.b];
    for (int k = 0; k < c.pointCount; ++k) {
        const RowPoint& p = c.p[k];
        // The anchors turn with their bodies: s = s₀ + n·(Δp_B − Δp_A), Δp = Δx + R(Δθ)·r − r.
        double dx = 0.0 - (a.dx + ((a.cos * p.rAx - a.sin * p.rAy) - p.rAx));
        double dy = 0.0 - (a.dy + ((a.sin * p.rAx + a.cos * p.rAy) - p.rAy));
        dx += b.dx + ((b.cos * p.rBx - b.sin * p.rBy) - p.rBx);
        dy += b.dy + ((b.sin * p.rBx + b.cos * p.rBy) - p.rBy);
        separation_[2 * i + k] = p.baseSeparation + (c.nx * dx + c.ny * dy);
    }
}

void ContactSolver::updateSeparations() {
    updateMotion(nullptr);
    if (lanesHold_) {
        forColours([&](std::size_t first, std::size_t end) {
            wide.measure(wide_.data() + first, wideCold_.data() + first, singleWide_.data() + first,
                         static_cast<int>(end - first), motion_.data());
        });
        for (const int i : overflow_) rowSeparations(static_cast<std::size_t>(i));
        return;
    }
    forChunks(rows_.size(), kRowGrain, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) rowSeparations(i);
    });
}

void ContactSolver::warmRow(std::size_t i) {
    const Row& c = rows_[i];
    const int world = static_cast<int>(bodies_.size());
    // The static world is in many rows of a colour: it is left as it is (zero velocity; its
    // zero inverse masses would leave it so), so that a colour's rows write disjoint bodies.
    BodyState* a = c.a == world ? nullptr : &state_[c.a];
    BodyState* b = c.b == world ? nullptr : &state_[c.b];
    const double tx = c.ny, ty = -c.nx;
    for (int k = 0; k < c.pointCount; ++k) {
        const RowPoint& p = c.p[k];
        const double n = p.normalImpulse - p.heldNormal;
        const double t = p.tangentImpulse - p.heldTangent;
        const double px = n * c.nx + t * tx;
        const double py = n * c.ny + t * ty;
        if (a) removeImpulse(*a, p.rAx, p.rAy, px, py);
        if (b) applyImpulse(*b, p.rBx, p.rBy, px, py);
    }
}

void ContactSolver::warmStart() {
    // The accumulated impulses, less what the held forces already gave in this inner sub-step
    // (the smooth step's share): Box2D's warm start, of which the method's step took its part.
    // In the sweep's order, colour by colour (a colour's rows share no dynamic body), then the
    // rows no colour took.
    const int world = static_cast<int>(bodies_.size());
    for (int colour = 0; colour < colours_; ++colour) {
        forColour(colour, [&](std::size_t first, std::size_t end) {
            if (wide.warm) {
                wide.warm(wide_.data() + first, wideCold_.data() + first,
                          singleWide_.data() + first, static_cast<int>(end - first), state_.data(),
                          world);
                return;
            }
            for (std::size_t slot = kLanes * first; slot < kLanes * end; ++slot)
                if (order_[slot] >= 0) warmRow(static_cast<std::size_t>(order_[slot]));
        });
    }
    for (const int i : overflow_) warmRow(static_cast<std::size_t>(i));
}

namespace {
// The solve's arithmetic, shared by the scalar row and (lane by lane, operation for operation)
// the wide loop (ContactWideLoop.inc): the relative velocity along (dx, dy) at a point whose
// anchors cross that direction as rA, rB; and an impulse d along it.
template <class State>
inline double along(const State& a, const State& b, double dx, double dy, double rA, double rB) {
    return (dx * (b.vx - a.vx) + dy * (b.vy - a.vy)) + (b.w * rB - a.w * rA);
}
template <class State>
inline void push(State& a, State& b, double d, double dx, double dy, double rA, double rB) {
    a.vx -= a.invMass * (d * dx);
    a.vy -= a.invMass * (d * dy);
    a.w -= a.invInertia * (rA * d);
    b.vx += b.invMass * (d * dx);
    b.vy += b.invMass * (d * dy);
    b.w += b.invInertia * (rB * d);
}

// The two points of a manifold solved together as a 2×2 linear complementarity problem, as in
// Box2D 2.4's block solver, with the soft terms added: for each point the converged soft
// constraint is v_n + bias + compliance·λ = 0 (λ ≥ 0, complementary). Solving the points one
// after the other instead leaves an asymmetry that tips tall stacks over.
template <class Row, class State>
inline bool solveBlock(Row& c, State& a, State& b) {
    auto& p1 = c.p[0];
    auto& p2 = c.p[1];
    const double k11 = c.k11, k22 = c.k22, k12 = c.k12, a12 = c.a12;

    const double linear = c.nx * (b.vx - a.vx) + c.ny * (b.vy - a.vy);
    const double vn1 = linear + (b.w * p1.rnB - a.w * p1.rnA);
    const double vn2 = linear + (b.w * p2.rnB - a.w * p2.rnA);
    const double old1 = p1.normalImpulse, old2 = p2.normalImpulse;
    // w = v_n(λ = 0) + bias: the velocity the points would have without any normal impulse.
    const double w1 = vn1 - (k11 * old1 + k12 * old2) + p1.bias;
    const double w2 = vn2 - (k12 * old1 + k22 * old2) + p2.bias;

    // x = −A⁻¹·w (A⁻¹ from preparePhase).
    double x1 = -(c.i11 * w1 + c.i12 * w2);
    double x2 = -(c.i12 * w1 + c.i22 * w2);
    if (!(x1 >= 0.0 && x2 >= 0.0)) {
        x1 = -w1 * c.invA11;  // point 1 alone
        x2 = 0.0;
        if (!(x1 >= 0.0 && a12 * x1 + w2 >= 0.0)) {
            x1 = 0.0;  // point 2 alone
            x2 = -w2 * c.invA22;
            if (!(x2 >= 0.0 && a12 * x2 + w1 >= 0.0)) {
                x2 = 0.0;  // neither
                if (!(w1 >= 0.0 && w2 >= 0.0)) return false;
            }
        }
    }
    // Both impulses at once: the bodies' velocities change once.
    const double d1 = x1 - old1, d2 = x2 - old2;
    const double sum = d1 + d2;
    a.vx -= a.invMass * (sum * c.nx);
    a.vy -= a.invMass * (sum * c.ny);
    a.w -= a.invInertia * (p1.rnA * d1 + p2.rnA * d2);
    b.vx += b.invMass * (sum * c.nx);
    b.vy += b.invMass * (sum * c.ny);
    b.w += b.invInertia * (p1.rnB * d1 + p2.rnB * d2);
    p1.normalImpulse = x1;
    p2.normalImpulse = x2;
    return true;
}
}  // namespace

void ContactSolver::solve() {
    // Colour by colour: the coloured rows four at a time (or one by one in the same order),
    // then those no colour took, one by one.
    const int world = static_cast<int>(bodies_.size());
    for (int colour = 0; colour < colours_; ++colour) {
        forColour(colour, [&](std::size_t first, std::size_t end) {
            if (wide.solve) {
                wide.solve(wide_.data() + first, singleWide_.data() + first,
                           static_cast<int>(end - first), state_.data(), world);
                return;
            }
            for (std::size_t slot = kLanes * first; slot < kLanes * end; ++slot)
                if (order_[slot] >= 0) solveRow(rows_[order_[slot]]);
        });
    }
    for (const int i : overflow_) solveRow(rows_[i]);
}

void ContactSolver::solveRow(Row& c) {
    // On copies, written back to every body but the static world: rows of one colour may be
    // solved by several workers at once, and the world is in many of them.
    const int world = static_cast<int>(bodies_.size());
    BodyState a = state_[c.a];
    BodyState b = state_[c.b];
    {
        if (!c.block || !solveBlock(c, a, b)) {
            for (int k = 0; k < c.pointCount; ++k) {
                RowPoint& p = c.p[k];
                if (p.effectiveMass == 0.0) continue;  // inactive in this phase
                const double vn = along(a, b, c.nx, c.ny, p.rnA, p.rnB);
                double impulse =
                    -p.effectiveMass * (vn + p.bias) - p.impulseScale * p.normalImpulse;
                const double accumulated = std::max(p.normalImpulse + impulse, 0.0);
                impulse = accumulated - p.normalImpulse;
                p.normalImpulse = accumulated;
                push(a, b, impulse, c.nx, c.ny, p.rnA, p.rnB);
            }
        }
        // Coulomb friction, each point bounded by its own normal impulse.
        const double tx = c.ny, ty = -c.nx;
        for (int k = 0; k < c.pointCount; ++k) {
            RowPoint& p = c.p[k];
            const double vt = along(a, b, tx, ty, p.rtA, p.rtB);
            const double limit = c.friction * p.normalImpulse;
            double impulse = -p.tangentMass * vt;
            const double accumulated = std::clamp(p.tangentImpulse + impulse, -limit, limit);
            impulse = accumulated - p.tangentImpulse;
            p.tangentImpulse = accumulated;
            push(a, b, impulse, tx, ty, p.rtA, p.rtB);
        }
    }
    if (c.a != world) state_[c.a] = a;
    if (c.b != world) state_[c.b] = b;
}

void ContactSolver::solveStep(double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                              const ContactSettings& settings, double positionWeight,
                              bool holding) {
    if (constraints_.empty()) return;
    // The smooth step's velocity change is spread evenly over the inner sub-steps (the
    // smooth forces held constant over the step); its position change is the integrator's, and
    // the solver adds to it only what the contact impulses change.
    const bool lengthsKnown = lastInnerH_ > 0.0 && lastStepH_ > 0.0;
    holding_ = holding && lengthsKnown;
    // The force the last step's impulses stood for becomes the bound of the next held force, in
    // stackSubsteps()' walk over the constraints.
    loadBodies(q0, u0, u);
    holdBodies(h);
    const int base = innerSubsteps(h, settings);
    const int n = stackSubsteps(h, base, settings);
    const double hi = h / n;
    // The warm-start impulses are per inner sub-step: rescaled when its length changes, they
    // stand for the same forces.
    const double warmScale = lastInnerH_ > 0.0 ? hi / lastInnerH_ : 1.0;
    // Sub-steps beyond the base buy stiffness: the frequency rises with the rate. (The held
    // forces are of the last step's lengths, which are replaced after.)
    buildRows(std::min(settings.hertz * n / base, 0.25 / hi), settings.dampingRatio, hi, warmScale);
    lastInnerH_ = hi;
    lastSubsteps_ = n;
    const std::size_t count = bodies_.size();
    // Gauss-Seidel converges more slowly where a contact joins very unequal masses (a heavy
    // box on a light one): there the solve iterates twice as often.
    const int iterations =
        settings.iterations * (largestMassRatio_ >= kMassRatioForMoreIterations ? 2 : 1);
    // Positions move only at the end of a sub-step's solve and when a bounce moves a body to
    // its time of impact, so separations are measured only then.
    bool moved = true;
    // A sub-step's share of the smooth step's velocity change; the velocity before the bounces
    // is kept where there are bounces (relax's pass below overwrites it otherwise).
    const bool bouncing = bounces();
    const auto smoothShare = [&](SolverBody& b, BodyState& s) {
        s.vx += b.smoothDv.x() / n;
        s.vy += b.smoothDv.y() / n;
        s.w += b.smoothDw / n;
        if (!bouncing) return;
        b.pushV = Vec2(s.vx, s.vy);
        b.pushW = s.w;
    };
    forChunks(count, kBodyGrain, [&](std::size_t first, std::size_t end) {
        for (std::size_t k = first; k < end; ++k) smoothShare(bodies_[k], state_[k]);
    });
    for (int i = 1; i <= n; ++i) {
        const double f = double(i) / n;
        if (bouncing) {
            if (moved) updateSeparations();
            moved = bounce(hi, n, settings);
            forChunks(count, kBodyGrain, [&](std::size_t first, std::size_t end) {
                for (std::size_t k = first; k < end; ++k) {
                    SolverBody& b = bodies_[k];
                    const BodyState& s = state_[k];
                    b.bounceDv += Vec2(s.vx, s.vy) - b.pushV;
                    b.bounceDw += s.w - b.pushW;
                }
            });
        }
        warmStart();
        if (moved) updateMotion(nullptr);
        preparePhase(hi, true, settings, moved);
        for (int it = 0; it < iterations; ++it) solve();
        // The sub-step's positions from the solve's velocities, and where relax measures the
        // separations, in one pass over the bodies.
        const SolveEnd solved{hi, f};
        updateMotion(&solved);
        moved = false;
        preparePhase(hi, false, settings, true);
        for (int it = 0; it < settings.relaxIterations; ++it) solve();
        bookClosings();
        // One pass over the bodies ends this sub-step and starts the next.
        const bool next = i < n;
        forChunks(count, kBodyGrain, [&](std::size_t first, std::size_t end) {
            for (std::size_t k = first; k < end; ++k) {
                SolverBody& b = bodies_[k];
                BodyState& s = state_[k];
                // What relax removed is the push-out's velocity: its displacement is the position
                // correction (the energy ledger's `correction`). But at a point that closed in the
                // sub-step relax stops an approach the soft solve let the body make for real: an
                // impact, the same whatever the push-out (bookClosings()).
                b.pushOut += hi * (b.pushV - Vec2(s.vx, s.vy) + b.impactDv);
                if (b.rotates) b.pushOutAngle += hi * (b.pushW - s.w + b.impactDw);
                b.impactDv = Vec2::Zero();
                b.impactDw = 0.0;
                if (next) smoothShare(b, s);
            }
        });
    }

    deepPushOut(h, settings);
    // The accumulated impulses, for the next step's warm start, all of them the solve's.
    lastStepH_ = h;
    keepStep(true);

    // A force held over the step moves a body by positionWeight·h·Δv under the user's method;
    // inner sub-stepping moved it by (n + 1)/(2n)·h·Δv. Moving it by the difference keeps a
    // resting body still whatever the integrator (the push-out, removed from the velocity by
    // relax, keeps its whole displacement: that is its purpose; a bounce acts at the instant
    // of impact, not as a force over the step).
    const double excess = positionWeight - (n + 1.0) / (2.0 * n);
    forChunks(count, kBodyGrain, [&](std::size_t first, std::size_t end) {
        for (std::size_t k = first; k < end; ++k) {
            SolverBody& b = bodies_[k];
            const BodyState& s = state_[k];
            const Vec2 v(s.vx, s.vy);
            const Vec2 dv = v - (b.v0 + b.smoothDv + b.bounceDv);
            const Vec2 press = b.smoothDv - b.heldDv;
            // Every velocity change here beyond the smooth step's is a contact impulse's, and so is
            // the held forces' share of that step.
            if (b.invMass > 0.0) b.stepImpulse += (v - (b.v0 + press)) / b.invMass;
            // Only a force held over the step moves a body by the method's weight: what the
            // contacts change beyond cancelling the smooth forces is an impact, which acts at once
            // (an inelastic stop at 200 m/s would otherwise be moved ±0.1·h·Δv: through a thin wall
            // under RK4, a metre short of it under symplectic Euler). The held forces moved it by
            // the method's weight already; where the contacts turn out to have been an impact, that
            // share is taken back to the impact's.
            const double held =
                std::min(1.0, press.norm() / std::max((dv + b.heldDv).norm(), 1e-300));
            const double weight = held * excess * h, heldBack = (held - 1.0) * excess * h;
            q.segment<2>(b.dof) += b.shift + weight * dv + heldBack * b.heldDv + b.timeShift;
            u.segment<2>(b.dof) = v;
            if (b.rotates) {
                const double dw = s.w - (b.w0 + b.smoothDw + b.bounceDw);
                q[b.dof + 2] += b.angleShift + weight * dw + heldBack * b.heldDw + b.angleTimeShift;
                u[b.dof + 2] = s.w;
            }
        }
    });
}

void ContactSolver::storeConstraint(std::size_t i, bool fromLanes, bool solved) {
    ContactConstraint& c = constraints_[i];
    const int at = fromLanes ? slot_[i] : -1;
    for (int k = 0; k < c.pointCount; ++k) {
        ContactPoint& p = c.points[k];
        if (at >= 0) {
            const WideRow::Point& w = wide_[at / kLanes].p[k];
            p.normalImpulse = w.normalImpulse[at % kLanes];
            p.tangentImpulse = w.tangentImpulse[at % kLanes];
        } else {
            p.normalImpulse = rows_[i].p[k].normalImpulse;
            p.tangentImpulse = rows_[i].p[k].tangentImpulse;
        }
        if (!solved) continue;
        p.solvedNormal = p.normalImpulse;
        p.solvedTangent = p.tangentImpulse;
    }
}

void ContactSolver::keepStep(bool solved) {
    // The accumulated impulses into the constraints and each point's held force from them
    // (refreshHeld(), once the step's lengths are known), in one walk: a constraint's held
    // forces read only its own impulses, just stored. The solve's impulses come straight from
    // the lanes: one pass over the rows fewer than unpacking them into rows_ first.
    const bool fromLanes = solved && lanesHold_;
    const bool hold = lastInnerH_ > 0.0 && lastStepH_ > 0.0;
    const double perSubstep = hold ? 1.0 / lastInnerH_ : 0.0;
    const double perStep = hold ? 1.0 / lastStepH_ : 0.0;
    forChunks(constraints_.size(), kRowGrain, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) {
            storeConstraint(i, fromLanes, solved);
            if (hold) holdConstraint(i, perSubstep, perStep);
        }
    });
}

}  // namespace phasebox
