#pragma once
/// \file
/// The per-pair properties of a World's materials (MaterialPairDef) as dense tables, rebuilt
/// when materials or pairs change, read through StepContext::pairs (dye diffusivity; the time-step limit).

#include <algorithm>
#include <span>
#include <vector>

#include <tide/defs.hpp>

namespace tide {

class MaterialPairs {
public:
    /// Tables for `materialCount` materials from the pairs set (later pairs override earlier).
    void build(std::size_t materialCount, std::span<const MaterialPairDef> pairs) {
        count_ = materialCount;
        diffusivity_.assign(count_ * count_, 0.0f);
        std::vector<bool> ownSet(count_, false);
        for (const MaterialPairDef& pair : pairs) {
            if (pair.a >= count_ || pair.b >= count_) continue;
            if (pair.a == pair.b) {
                diffusivity_[pair.a * count_ + pair.a] = pair.diffusivity;
                ownSet[pair.a] = true;
            } else if (pair.miscible) {
                diffusivity_[pair.a * count_ + pair.b] = diffusivity_[pair.b * count_ + pair.a] = pair.diffusivity;
            }
        }
        // A material's own diffusivity, unless set: the largest of its miscible pairs.
        for (std::size_t a = 0; a < count_; ++a) {
            if (ownSet[a]) continue;
            float own = 0.0f;
            for (std::size_t b = 0; b < count_; ++b)
                if (b != a) own = std::max(own, diffusivity_[a * count_ + b]);
            diffusivity_[a * count_ + a] = own;
        }
        maxDiffusivity_ = 0.0f;
        for (const float d : diffusivity_) maxDiffusivity_ = std::max(maxDiffusivity_, d);
    }

    /// D of the dye between materials a and b, m²/s (0: no exchange).
    [[nodiscard]] float diffusivity(MaterialIndex a, MaterialIndex b) const { return diffusivity_[a * count_ + b]; }
    [[nodiscard]] float maxDiffusivity() const { return maxDiffusivity_; }
    [[nodiscard]] bool anyDiffusion() const { return maxDiffusivity_ > 0.0f; }

private:
    std::size_t count_ = 0;
    std::vector<float> diffusivity_;
    float maxDiffusivity_ = 0.0f;
};

}  // namespace tide
