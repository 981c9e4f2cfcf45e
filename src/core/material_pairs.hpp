#pragma once
/// \file
/// The per-pair properties of a World's materials (MaterialPairDef) as dense tables, rebuilt
/// when materials or pairs change, read by the solvers through StepContext::pairs.

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
        tension_.assign(count_ * count_, 0.0f);
        std::vector<bool> ownSet(count_, false);
        for (const MaterialPairDef& pair : pairs) {
            if (pair.a >= count_ || pair.b >= count_) continue;
            tension_[pair.a * count_ + pair.b] = tension_[pair.b * count_ + pair.a] = pair.surfaceTension;
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
        anyTension_ = false;
        for (const float d : diffusivity_) maxDiffusivity_ = std::max(maxDiffusivity_, d);
        for (const float t : tension_) anyTension_ = anyTension_ || t > 0.0f;
    }

    /// D of the dye between materials a and b, m²/s (0: no exchange).
    [[nodiscard]] float diffusivity(MaterialIndex a, MaterialIndex b) const { return diffusivity_[a * count_ + b]; }
    /// γ of the Akinci et al. 2013 surface tension between a and b (0: none).
    [[nodiscard]] float surfaceTension(MaterialIndex a, MaterialIndex b) const { return tension_[a * count_ + b]; }
    [[nodiscard]] float maxDiffusivity() const { return maxDiffusivity_; }
    [[nodiscard]] bool anyDiffusion() const { return maxDiffusivity_ > 0.0f; }
    [[nodiscard]] bool anyTension() const { return anyTension_; }

private:
    std::size_t count_ = 0;
    std::vector<float> diffusivity_;
    std::vector<float> tension_;
    float maxDiffusivity_ = 0.0f;
    bool anyTension_ = false;
};

}  // namespace tide
