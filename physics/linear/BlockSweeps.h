#pragma once
// The inner loops of the multigrid on 2 × 2 blocks (points' (x, y) pairs), over compressed
// block rows: 4 doubles per block, row-major; column[k] is block k's first DOF.
//
// Each loop exists twice: on two-lane vectors (any x86-64 or other processor), and on
// four-lane ones with fused multiply-adds, where a block times its point is one instruction
// (x86-64 processors with AVX2 and FMA, found at run time). The wide loops round differently
// (a fused multiply-add rounds once), so the last bits of a result depend on the processor;
// each is deterministic on its own.

namespace phasebox::blocks {

struct Rows {
    int nodes = 0;
    const int* outer = nullptr;     // nodes + 1 offsets into column and (×4) values
    const int* diagonal = nullptr;  // index of each row's diagonal block (the sweeps only)
    const int* column = nullptr;
    const double* values = nullptr;
};

// y = A·x.
void multiply(const Rows& a, const double* x, double* y);
// Forward block Gauss–Seidel from x = 0: x_i = D_i⁻¹·(b_i − Σ_{j<i} A_ij·x_j) in row order;
// inverse holds the 2 × 2 inverses of the diagonal blocks.
void forward(const Rows& a, const double* inverse, const double* b, double* x);
// coarse[toCoarse[i]] −= Σ_{j>i} A_ij·x_j: after forward(), that is b − A·x restricted to the
// next level (each node's value added into its aggregate's).
void restrictUpper(const Rows& a, const int* toCoarse, const double* x, double* coarse);
// Backward block Gauss–Seidel over whole rows: x_i += D_i⁻¹·(b_i − Σ_j A_ij·x_j), last row first.
void backward(const Rows& a, const double* inverse, const double* b, double* x);
// y ← L⁻¹·y for a block-unit lower triangular L given by its blocks left of the diagonal.
void lowerSolve(const Rows& l, double* y);
// y ← U⁻¹·D⁻¹·y for a block-unit upper triangular U given by its blocks right of the diagonal,
// and the inverses of D's 2 × 2 blocks.
void upperSolve(const Rows& u, const double* inverse, double* y);

// For tests: turns the wide loops off (false) or back on where the processor has them (true);
// returns whether they now run.
bool setWide(bool on);

}  // namespace phasebox::blocks
