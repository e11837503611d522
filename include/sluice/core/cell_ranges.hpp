#pragma once
// Where each cell's particles are in the sorted arrays: [begin(c), end(c)), for the cells a
// rank holds particles in (its own, written by the rebin, and its halo's, written by the halo
// unpacks). Every other cell reads as empty and costs nothing: the ranges live in an
// open-addressing hash table (linear probing, at most half full) keyed by the cell's global
// index, so a rank's memory follows its occupied cells, not the grid (docs/ARCHITECTURE.md,
// "Cell storage").
//
// The halo unpacks of different peers run as concurrent tasks and insert distinct cells, while
// other tasks may look up cells: slots are claimed with an atomic compare-and-swap on the key,
// and keys are read with relaxed atomic loads (a plain load on x86-64). Room for the inserts
// must be reserved beforehand (reserve), on one thread, since growing rehashes.
#include "sluice/core/cell_grid.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <vector>

namespace sluice {

class CellRanges {
public:
    struct Range {
        std::uint32_t begin = 0, end = 0;
    };

    // Bytes the table takes for `cells` stored cells (the slots that reserve(cells) allocates):
    // the term of a rank's memory estimate that the cell storage adds.
    [[nodiscard]] static std::size_t bytes_for(std::size_t cells) {
        return slots_for(cells) * kBytesPerSlot;
    }
    static constexpr std::size_t kBytesPerSlot = sizeof(CellIndex) + sizeof(Range);

    // Every range empty, with room for `cells` cells without growing. A table up to 4 times
    // larger than needed is kept and cleared (the halo's reserve grows it again every rebuild).
    void reset(std::size_t cells) {
        const std::size_t slots = slots_for(cells);
        if (slots > key_.size() || 4 * slots < key_.size()) {
            key_.assign(slots, kEmpty);
            range_.assign(slots, Range{});
            mask_ = slots - 1;
            shift_ = 64 - bits_of(slots);
        } else if (stored_ > 0) {
            std::fill(key_.begin(), key_.end(), kEmpty);
        }
        stored_ = 0;
    }

    // Room for `more` cells beyond those stored (rehashes when the table would pass half
    // full; not safe while other threads use the table).
    void reserve(std::size_t more) {
        if (!key_.empty() && 2 * (stored_ + more) <= key_.size())
            return;
        std::vector<CellIndex> keys;
        std::vector<Range> ranges;
        keys.swap(key_);
        ranges.swap(range_);
        reset(stored_ + more);
        for (std::size_t s = 0; s < keys.size(); ++s)
            if (keys[s] != kEmpty)
                set(keys[s], ranges[s].begin, ranges[s].end);
    }

    // Sets c's range, replacing any it had. Concurrent calls for distinct cells are safe
    // within the room reserved.
    void set(CellIndex c, std::uint32_t begin, std::uint32_t end) {
        for (std::size_t s = slot_of(c);; s = (s + 1) & mask_) {
            std::atomic_ref<CellIndex> key(key_[s]);
            CellIndex seen = key.load(std::memory_order_relaxed);
            if (seen == kEmpty && key.compare_exchange_strong(seen, c, std::memory_order_relaxed)) {
                std::atomic_ref<std::size_t>(stored_).fetch_add(1, std::memory_order_relaxed);
                range_[s] = {begin, end};
                return;
            }
            if (seen == c) {
                range_[s] = {begin, end};
                return;
            }
        }
    }

    [[nodiscard]] Range range(CellIndex c) const {
        if (key_.empty())
            return {};
        for (std::size_t s = slot_of(c);; s = (s + 1) & mask_) {
            const CellIndex seen = std::atomic_ref<CellIndex>(const_cast<CellIndex&>(key_[s]))
                                       .load(std::memory_order_relaxed);
            if (seen == c)
                return range_[s];
            if (seen == kEmpty)
                return {};
        }
    }
    [[nodiscard]] std::uint32_t begin(CellIndex c) const { return range(c).begin; }
    [[nodiscard]] std::uint32_t end(CellIndex c) const { return range(c).end; }

    [[nodiscard]] std::size_t stored() const { return stored_; } // cells set since the reset
    [[nodiscard]] std::size_t slots() const { return key_.size(); }
    [[nodiscard]] std::size_t bytes() const { return key_.capacity() * kBytesPerSlot; }

private:
    static constexpr CellIndex kEmpty = ~CellIndex{0}; // no cell has this index
    // At least twice the cells (a probe then ends after ~1.5 slots on average) and a power of
    // two; 16 slots at least.
    [[nodiscard]] static std::size_t slots_for(std::size_t cells) {
        std::size_t s = 16;
        while (s < 2 * cells)
            s *= 2;
        return s;
    }
    [[nodiscard]] static int bits_of(std::size_t pow2) {
        int b = 0;
        while ((std::size_t{1} << b) < pow2)
            ++b;
        return b;
    }
    // Runs of 4 cells along x (consecutive indices) share 4 consecutive slots, one cache line:
    // a neighbour loop's 3^D lookups touch about half as many lines. The runs are spread over
    // the table by Fibonacci hashing (the top bits of the run's index times 2^64 / golden
    // ratio).
    [[nodiscard]] std::size_t slot_of(CellIndex c) const {
        return ((static_cast<std::size_t>(((c >> 2) * 0x9E3779B97F4A7C15ull) >> (shift_ + 2))
                 << 2) |
                static_cast<std::size_t>(c & 3)) &
               mask_;
    }

    std::vector<CellIndex> key_;
    std::vector<Range> range_;
    std::size_t mask_ = 0;
    int shift_ = 64;
    std::size_t stored_ = 0;
};

} // namespace sluice
