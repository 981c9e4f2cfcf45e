#pragma once
/// \file
/// The per-pair properties of a World's materials (MaterialPairDef) as dense tables, rebuilt
/// when materials or pairs change, read through StepContext::pairs (dye diffusivity and the
/// surface/interface tension γ of Akinci et al. 2013; the time-step limit).

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
        hasTension_.assign(count_, 0);
        anyTension_ = false;
        std::vector<bool> ownSet(count_, false);
        for (const MaterialPairDef& pair : pairs) {
            if (pair.a >= count_ || pair.b >= count_) continue;
            tension_[pair.a * count_ + pair.b] = tension_[pair.b * count_ + pair.a] = pair.surfaceTension;
            if (pair.surfaceTension > 0.0f) hasTension_[pair.a] = hasTension_[pair.b] = 1;
            anyTension_ = anyTension_ || pair.surfaceTension > 0.0f;
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
    /// γ of Akinci et al. 2013 between materials a and b (a == b: surface tension of a).
    [[nodiscard]] float tension(MaterialIndex a, MaterialIndex b) const { return tension_[a * count_ + b]; }
    /// Whether material a has a pair with γ > 0.
    [[nodiscard]] bool hasTension(MaterialIndex a) const { return hasTension_[a] != 0; }
    [[nodiscard]] bool anyTension() const { return anyTension_; }

private:
    std::size_t count_ = 0;
    std::vector<float> diffusivity_;
    std::vector<float> tension_;
    std::vector<unsigned char> hasTension_;
    bool anyTension_ = false;
    float maxDiffusivity_ = 0.0f;
};

}  // namespace tide
