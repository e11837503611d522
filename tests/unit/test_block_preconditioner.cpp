// The block-Jacobi preconditioner of the projection scheme's pressure solve
// (include/sluice/solver/block_preconditioner.hpp) on the Poisson problem of
// scaled_poisson_grid.hpp (u = x^2 + y^2 on a 16 x 16 grid, the scheme's row-scaled form,
// reproduced exactly by the 5-point stencil). One block holding
// every row is the exact inverse; four blocks make a block-Jacobi iteration that converges to
// the same answer in fewer sweeps than point Jacobi (the row scaling alone), and so does ILU(0)
// of the same blocks.
#include "sluice/solver/block_preconditioner.hpp"

#include "scaled_poisson_grid.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace sluice;

namespace {

constexpr int n = 16;
const testing::ScaledPoissonGrid grid(n);

void poisson(Eigen::SparseMatrix<double>& A, Eigen::VectorXd& b) {
    grid.assemble(A, b);
}
double max_error(const Eigen::VectorXd& u) {
    return grid.max_error(u);
}

// Stationary iteration u += M^{-1} (b - A u) from u = 0 until |b - A u| <= 1e-10 |b|, with M
// block-diagonal over `blocks` contiguous row ranges (1 range of n*n rows each = point Jacobi
// when every block is one row). Returns the sweeps.
int block_jacobi_sweeps(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                        int block_rows, Eigen::VectorXd& u, BlockMethod method = BlockMethod::lu) {
    const int rows = static_cast<int>(A.rows());
    std::vector<BlockFactor> factors;
    for (int lo = 0; lo < rows; lo += block_rows) {
        const int m = std::min(block_rows, rows - lo);
        factors.emplace_back();
        if (m > 1)
            REQUIRE(factors.back().factor(A.block(lo, lo, m, m), method));
    }
    u = Eigen::VectorXd::Zero(rows);
    for (int sweep = 1; sweep <= 100000; ++sweep) {
        Eigen::VectorXd r = b - A * u;
        if (r.norm() <= 1e-10 * b.norm())
            return sweep - 1;
        for (int k = 0, lo = 0; lo < rows; lo += block_rows, ++k) {
            const int m = std::min(block_rows, rows - lo);
            factors[static_cast<std::size_t>(k)].solve(r.segment(lo, m)); // identity if m = 1
        }
        u += r;
    }
    return -1;
}

} // namespace

TEST_CASE("block preconditioner: one block over the whole system is its exact inverse") {
    Eigen::SparseMatrix<double> A;
    Eigen::VectorXd b;
    poisson(A, b);
    BlockFactor f;
    REQUIRE(f.factor(A));
    CHECK(f.ready());
    Eigen::VectorXd u = b;
    f.solve(u);
    const double err = max_error(u);
    std::printf("direct solve of the %d x %d Poisson problem: max error %.2e\n", n, n, err);
    CHECK(err < 1e-12);
}

TEST_CASE("block preconditioner: block-Jacobi converges to the known answer in fewer sweeps") {
    Eigen::SparseMatrix<double> A;
    Eigen::VectorXd b;
    poisson(A, b);
    Eigen::VectorXd u_point, u_block;
    const int point = block_jacobi_sweeps(A, b, 1, u_point);
    const int blocks = block_jacobi_sweeps(A, b, n * n / 4, u_block); // 4 strips of 4 rows
    std::printf("Poisson %d x %d: point Jacobi %d sweeps (error %.2e), 4-block Jacobi %d sweeps "
                "(error %.2e)\n",
                n, n, point, max_error(u_point), blocks, max_error(u_block));
    REQUIRE(point > 0);
    REQUIRE(blocks > 0);
    CHECK(max_error(u_point) < 1e-8);
    CHECK(max_error(u_block) < 1e-8);
    CHECK((u_point - u_block).cwiseAbs().maxCoeff() < 1e-8);
    // Strips of 4 grid rows: the coupling left to the iteration is across 3 strip boundaries
    // only; the iteration's error decays at least 4 times faster per sweep.
    CHECK(4 * blocks < point);
    // ILU(0) of the same strips (no fill: an approximation of each strip's inverse) converges
    // to the same answer, between the two.
    Eigen::VectorXd u_ilu;
    const int ilu = block_jacobi_sweeps(A, b, n * n / 4, u_ilu, BlockMethod::ilu0);
    std::printf("4-block ILU(0) %d sweeps (error %.2e)\n", ilu, max_error(u_ilu));
    REQUIRE(ilu > 0);
    CHECK(max_error(u_ilu) < 1e-8);
    CHECK(ilu < point);
    CHECK(ilu > blocks);
}

TEST_CASE("block preconditioner: ILU(0) of a tridiagonal matrix is its exact LU") {
    // 1-D Poisson u'' = 2, u = x^2 on [0, 1]: the factors of a tridiagonal matrix have no fill,
    // so ILU(0) is exact and one application solves the system.
    const int m = 50;
    const double hx = 1.0 / (m - 1);
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd b(m);
    for (int i = 0; i < m; ++i) {
        t.emplace_back(i, i, 1.0);
        if (i == 0 || i == m - 1) {
            b[i] = (i * hx) * (i * hx);
            continue;
        }
        t.emplace_back(i, i - 1, -0.5);
        t.emplace_back(i, i + 1, -0.5);
        b[i] = -hx * hx / 2 * 2.0;
    }
    Eigen::SparseMatrix<double> A(m, m);
    A.setFromTriplets(t.begin(), t.end());
    BlockFactor f;
    REQUIRE(f.factor(A, BlockMethod::ilu0));
    f.solve(b);
    double err = 0;
    for (int i = 0; i < m; ++i)
        err = std::max(err, std::abs(b[i] - (i * hx) * (i * hx)));
    CHECK(err < 1e-12);
}

TEST_CASE("block preconditioner: a singular block leaves the identity") {
    for (const BlockMethod method : {BlockMethod::lu, BlockMethod::ilu0}) {
        Eigen::SparseMatrix<double> S(2, 2);
        S.insert(0, 0) = 1;
        S.insert(0, 1) = 1;
        S.insert(1, 0) = 1;
        S.insert(1, 1) = 1;
        S.makeCompressed();
        BlockFactor f;
        CHECK_FALSE(f.factor(S, method));
        CHECK_FALSE(f.ready());
        Eigen::VectorXd x(2);
        x << 3, 4;
        f.solve(x);
        CHECK(x[0] == 3);
        CHECK(x[1] == 4);
    }
}
