// A Poisson problem with a known answer in the row-scaled form of the projection scheme's
// pressure system, shared by the preconditioner tests (test_block_preconditioner,
// test_coarse_system): the 5-point Laplacian on an n x n grid,
//   u_i - 1/4 sum_{j in N(i)} u_j = -h^2/4 f_i   (interior),   u_i = u_exact (boundary),
// with u = x^2 + y^2, f = 4, which the 5-point stencil reproduces exactly. The boundary rows
// play the scheme's Dirichlet (free-surface) rows.
#pragma once

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sluice::testing {

struct ScaledPoissonGrid {
    int n;    // grid points per side, boundary included
    double h; // spacing on the unit square

    explicit ScaledPoissonGrid(int points) : n(points), h(1.0 / (points - 1)) {}

    int id(int ix, int iy) const { return iy * n + ix; }
    double exact(int ix, int iy) const {
        const double x = ix * h, y = iy * h;
        return x * x + y * y;
    }
    bool boundary(int ix, int iy) const { return ix == 0 || iy == 0 || ix == n - 1 || iy == n - 1; }

    // The scaled system A u = b over the whole grid.
    template <class Matrix>
    void assemble(Matrix& A, Eigen::VectorXd& b) const {
        std::vector<Eigen::Triplet<double>> t;
        b.resize(n * n);
        for (int iy = 0; iy < n; ++iy)
            for (int ix = 0; ix < n; ++ix) {
                const int i = id(ix, iy);
                t.emplace_back(i, i, 1.0);
                if (boundary(ix, iy)) {
                    b[i] = exact(ix, iy);
                    continue;
                }
                for (const int j : {id(ix - 1, iy), id(ix + 1, iy), id(ix, iy - 1), id(ix, iy + 1)})
                    t.emplace_back(i, j, -0.25);
                b[i] = -h * h / 4 * 4.0;
            }
        A.resize(n * n, n * n);
        A.setFromTriplets(t.begin(), t.end());
    }

    double max_error(const Eigen::VectorXd& u) const {
        double e = 0;
        for (int iy = 0; iy < n; ++iy)
            for (int ix = 0; ix < n; ++ix)
                e = std::max(e, std::abs(u[id(ix, iy)] - exact(ix, iy)));
        return e;
    }
};

} // namespace sluice::testing
