#pragma once
// Block-Jacobi preconditioner of the projection scheme's pressure system (docs/PROJECTION.md,
// "Preconditioner"): for one cell group, a factorisation of the group's diagonal block of the
// row-scaled matrix A = I - [a_ij] (couplings to particles of other groups and ranks dropped),
// either the exact sparse LU or the incomplete LU without fill, ILU(0) (Saad 2003,
// "Iterative Methods for Sparse Linear Systems", 2nd ed., section 10.3.2, Algorithm 10.4).
// Applying it, z = M_g^{-1} r on the group's rows, needs no other group's data, so it runs
// inside the group's task; M = diag(M_g) is assembled per group, per step, from the
// coefficients the step computed.
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace sluice {

enum class BlockMethod { lu, ilu0 };

// A square block in compressed rows: row r holds the entries [outer[r], outer[r + 1]) of col
// and val, columns strictly increasing (what ILU(0) works on in place).
struct BlockRows {
    std::vector<int> outer, col;
    std::vector<double> val;
    [[nodiscard]] int rows() const {
        return outer.empty() ? 0 : static_cast<int>(outer.size()) - 1;
    }
};

class BlockFactor {
public:
    BlockFactor();
    ~BlockFactor();
    BlockFactor(BlockFactor&&) noexcept;
    BlockFactor& operator=(BlockFactor&&) noexcept;
    BlockFactor(const BlockFactor&) = delete;
    BlockFactor& operator=(const BlockFactor&) = delete;

    // Factorises `block` (square; every diagonal entry present for ILU(0)). False when the
    // factorisation fails (a singular block, a zero pivot): solve() is then the identity, i.e.
    // the group falls back to the row scaling alone.
    bool factor(const Eigen::SparseMatrix<double>& block, BlockMethod method = BlockMethod::lu);
    // The same from compressed rows, assembled by the caller without a sort or a copy: the
    // buffers are swapped in, and `block` gets back those of the previous factorisation (so
    // that both keep their capacity from step to step).
    bool factor(BlockRows& block, BlockMethod method);
    // x <- M^{-1} x (the identity before factor() succeeded).
    void solve(Eigen::Ref<Eigen::VectorXd> x) const;
    [[nodiscard]] bool ready() const;
    [[nodiscard]] long size() const; // rows of the factorised block (0 before factor())

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace sluice
