#pragma once
// GLSL 3.30 sources of every pass, as raw strings. Programs are put together from pieces:
// kVersion + shared functions (kSky, kColormap) + the stage's body.

#include <initializer_list>
#include <string>

namespace tide::render::shaders {

inline constexpr const char* kVersion = "#version 330 core\n";

/// A stage's source: kVersion, then the pieces in order.
inline std::string compose(std::initializer_list<const char*> pieces) {
    std::string s = kVersion;
    for (const char* p : pieces) s += p;
    return s;
}

/// The environment both the background and the water's reflections show: a sky gradient with
/// a sun, and below the horizon a neutral ground colour.
inline constexpr const char* kSky = R"(
uniform vec3 uSunDirection;   // world, towards the sun, unit
vec3 skyColor(vec3 dir) {
    vec3 zenith = vec3(0.22, 0.45, 0.82);
    vec3 horizon = vec3(0.78, 0.86, 0.95);
    vec3 sky = dir.y >= 0.0 ? mix(horizon, zenith, pow(clamp(dir.y, 0.0, 1.0), 0.55))
                            : mix(horizon, vec3(0.42, 0.40, 0.36), clamp(-dir.y * 4.0, 0.0, 1.0));
    float toSun = max(dot(dir, uSunDirection), 0.0);
    return sky + vec3(1.0, 0.95, 0.85) * (pow(toSun, 900.0) * 6.0 + pow(toSun, 12.0) * 0.12);
}
)";

/// The sea seen from above, shaded as the surface pass shades the near field's water
/// (kCompositeFragment): Schlick's Fresnel between the sky's reflection and what comes up
/// through the water, the floor's sand absorbed along `path` metres of water (Beer–Lambert,
/// per channel, with the surface pass's uAbsorption) over the water's own colour darkened,
/// and the sun's highlight. n: the surface normal, v: towards the eye (world, unit).
inline constexpr const char* kDeepWater = R"(
uniform vec3 uWaterColor;
uniform float uAbsorption;   // per metre, of the colours the water does not have
vec3 deepWater(vec3 n, vec3 v, float path) {
    float fresnel = 0.02 + 0.98 * pow(1.0 - max(dot(n, v), 0.0), 5.0);
    vec3 lacking = vec3(1.0) - uWaterColor;
    vec3 transmitted = exp(-uAbsorption * (lacking * lacking + 0.04) * path);
    vec3 floorColor = vec3(0.80, 0.72, 0.56) * (0.55 + 0.45 * max(uSunDirection.y, 0.0));
    vec3 refracted = floorColor * transmitted + uWaterColor * 0.3 * (vec3(1.0) - transmitted);
    vec3 color = mix(refracted, skyColor(reflect(-v, n)), fresnel);
    vec3 h = normalize(uSunDirection + v);
    return color + vec3(1.0, 0.96, 0.88) * pow(max(dot(n, h), 0.0), 350.0) * 1.5;
}
)";

/// Full-screen triangle from gl_VertexID, no attributes.
inline constexpr const char* kFullscreenVertex = R"(
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

/// Sky, and a sand-coloured chequered ground at the container's floor, with depth, so that
/// particles below the horizon are hidden by nothing but the ground itself.
inline constexpr const char* kBackgroundFragment = R"(
uniform mat4 uInverseViewProjection;
uniform mat4 uViewProjection;
uniform vec3 uEye;
uniform vec2 uTexel;
uniform float uGroundY;
uniform float uTile;
uniform float uFogDistance;
uniform int uOcean;       // 1: an ocean scene (uSeaY, uNearMin, uNearMax)
uniform float uSeaY;      // still water, world y
uniform float uSeaDepth;  // m
uniform vec2 uNearMin;    // the near field's x–z rectangle
uniform vec2 uNearMax;
out vec4 fragColor;
void main() {
    vec2 ndc = gl_FragCoord.xy * uTexel * 2.0 - 1.0;
    vec4 a = uInverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 b = uInverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 dir = normalize(b.xyz / b.w - a.xyz / a.w);
    float t = dir.y < -1e-5 ? (uGroundY - uEye.y) / dir.y : -1.0;
    if (t <= 0.0) {
        fragColor = vec4(skyColor(dir), 1.0);
        gl_FragDepth = 1.0;
        return;
    }
    vec3 hit = uEye + t * dir;
    // An ocean: beyond the near field the ground is the sea's still water (the far field's
    // mesh covers it out to its edge), flat and fogged to the horizon like the mesh.
    if (uOcean != 0 && dir.y < -1e-5) {
        float ts = (uSeaY - uEye.y) / dir.y;
        vec3 sea = uEye + ts * dir;
        if (ts > 0.0 && (any(lessThan(sea.xz, uNearMin)) || any(greaterThan(sea.xz, uNearMax)))) {
            float fog = 1.0 - exp(-ts / uFogDistance);
            vec3 water = deepWater(vec3(0.0, 1.0, 0.0), -dir, uSeaDepth / max(-dir.y, 0.02));
            fragColor = vec4(mix(water, skyColor(vec3(dir.x, 0.0, dir.z)), fog), 1.0);
            vec4 clip = uViewProjection * vec4(sea, 1.0);
            gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
            return;
        }
    }
    ivec2 cell = ivec2(floor(hit.xz / uTile));
    float checker = ((cell.x + cell.y) & 1) == 0 ? 1.0 : 0.92;
    vec3 sand = vec3(0.80, 0.72, 0.56) * checker * (0.55 + 0.45 * max(uSunDirection.y, 0.0));
    float fog = 1.0 - exp(-t / uFogDistance);
    fragColor = vec4(mix(sand, skyColor(vec3(dir.x, 0.0, dir.z)), fog), 1.0);
    vec4 clip = uViewProjection * vec4(hit, 1.0);
    gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
}
)";

/// The far field's surface (far_field_sea.hpp): a mesh in world coordinates, shaded as deep
/// water, fogged towards the horizon. Drawn twice: behind the particles, cut away over the
/// near field, where their own surface is drawn (uZones 0); then over their shaded surface in
/// the coupling zones only (uZones 1), opaque at the open faces and fading (smoothstep) to
/// nothing at the zones' inner edges, as the zones hand the particles from the far field's
/// motion to their own: no seam at the open faces.
inline constexpr const char* kFarFieldVertex = R"(
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uViewProjection;
out vec3 vPosition;
out vec3 vNormal;
void main() {
    vPosition = aPosition;
    vNormal = aNormal;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";
inline constexpr const char* kFarFieldFragment = R"(
uniform vec3 uEye;
uniform vec2 uNearMin;
uniform vec2 uNearMax;
uniform float uFogDistance;
uniform float uSeaDepth;     // still water over the floor, m
uniform int uZones;          // 0: around the near field; 1: over its coupling zones
uniform vec4 uOpen;          // 1 where the face is open: -x, +x, -z, +z
uniform float uZoneWidth;    // m
in vec3 vPosition;
in vec3 vNormal;
out vec4 fragColor;
void main() {
    bool inside = all(greaterThan(vPosition.xz, uNearMin)) && all(lessThan(vPosition.xz, uNearMax));
    float alpha = 1.0;
    if (uZones == 0) {
        if (inside) discard;
    } else {
        if (!inside) discard;
        vec4 in_ = vec4(vPosition.x - uNearMin.x, uNearMax.x - vPosition.x, vPosition.z - uNearMin.y, uNearMax.y - vPosition.z);
        vec4 chi = clamp(1.0 - in_ / uZoneWidth, 0.0, 1.0) * uOpen;  // 1 at an open face, 0 at the zone's inner edge
        float c = max(max(chi.x, chi.y), max(chi.z, chi.w));
        alpha = c * c * (3.0 - 2.0 * c);
        if (alpha <= 0.0) discard;
    }
    vec3 toEye = uEye - vPosition;
    float distance = length(toEye);
    vec3 v = toEye / distance;
    vec3 n = normalize(vNormal);
    if (dot(n, v) < 0.0) n = normalize(n - 2.0 * dot(n, v) * v);  // a back-facing slope at grazing view
    float fog = 1.0 - exp(-distance / uFogDistance);
    vec3 water = deepWater(n, v, uSeaDepth / max(v.y, 0.02));
    fragColor = vec4(mix(water, skyColor(vec3(-v.x, 0.0, -v.z)), fog), alpha);
}
)";

/// The container's edges.
inline constexpr const char* kLinesVertex = R"(
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProjection;
void main() { gl_Position = uViewProjection * vec4(aPosition, 1.0); }
)";
inline constexpr const char* kLinesFragment = R"(
uniform vec3 uColor;
out vec4 fragColor;
void main() { fragColor = vec4(uColor, 1.0); }
)";

/// Obstacles: lit, stone-grey solids.
inline constexpr const char* kSolidVertex = R"(
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uViewProjection;
out vec3 vNormal;
void main() {
    vNormal = aNormal;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";
inline constexpr const char* kSolidFragment = R"(
uniform vec3 uSunDirection;
in vec3 vNormal;
out vec4 fragColor;
void main() {
    vec3 n = normalize(vNormal);
    float light = 0.35 + 0.65 * max(dot(n, uSunDirection), 0.0) + 0.1 * n.y;
    fragColor = vec4(vec3(0.52, 0.5, 0.47) * light, 1.0);
}
)";

/// Five stops of a perceptual colour map (viridis), interpolated linearly.
inline constexpr const char* kColormap = R"(
uniform vec3 uColormap[5];
vec3 colormap(float t) {
    t = clamp(t, 0.0, 1.0) * 4.0;
    int i = min(int(t), 3);
    return mix(uColormap[i], uColormap[i + 1], t - float(i));
}
)";

/// Every particle as a point sprite, sized to cover its sphere on screen; shared by the
/// particle, depth and thickness passes.
inline constexpr const char* kSphereVertex = R"(
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aVelocity;
layout(location = 2) in float aDensity;
layout(location = 3) in float aPressure;
layout(location = 4) in uint aMaterial;
uniform mat4 uView;
uniform mat4 uProjection;
uniform float uRadius;        // sphere radius, m
uniform float uPointScale;    // viewport height × projection[1][1]: diameter px = scale · r / depth
uniform uint uVisible;        // bit m set: material m is drawn
uniform int uColorBy;         // 0 material, 1 speed, 2 density, 3 pressure
uniform vec2 uRange;
uniform vec3 uMaterialColor[16];
uniform float uRestDensity[16];
uniform vec2 uFoamSpeed;      // speeds at which whitecaps start and saturate, m/s
out vec3 vCentre;             // eye space
out vec3 vColor;
out float vFoam;
void main() {
    uint m = min(aMaterial, 15u);
    vColor = uMaterialColor[m];
    vFoam = 0.0;
    vec4 eye = uView * vec4(aPosition, 1.0);
    vCentre = eye.xyz;
    if (((uVisible >> m) & 1u) == 0u) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // outside the clip volume: dropped
        gl_PointSize = 1.0;
        return;
    }
    gl_Position = uProjection * eye;
    gl_PointSize = max(uPointScale * uRadius / max(-eye.z, 1e-4), 1.0);
    float speed = length(aVelocity);
    if (uColorBy != 0) {
        float value = uColorBy == 1 ? speed : (uColorBy == 2 ? aDensity : aPressure);
        vColor = colormap((value - uRange.x) / max(uRange.y - uRange.x, 1e-6));
    }
    // Whitecaps, after the potentials of Ihmsen et al. 2012 reduced to what one particle
    // knows: fast (trapped air) and under-dense (a thin crest or spray at the surface).
    float crest = clamp((1.0 - aDensity / uRestDensity[m]) / 0.25, 0.0, 1.0);
    vFoam = smoothstep(uFoamSpeed.x, uFoamSpeed.y, speed) * (0.3 + 0.7 * crest);
}
)";

/// The sphere under a sprite's fragment: eye-space normal and point, and its window depth.
inline constexpr const char* kSphereFragmentCommon = R"(
in vec3 vCentre;
in vec3 vColor;
in float vFoam;
uniform mat4 uProjection;
uniform float uRadius;
vec3 sphereNormal() {
    vec2 c = gl_PointCoord * 2.0 - 1.0;
    c.y = -c.y;
    float r2 = dot(c, c);
    if (r2 > 1.0) discard;
    return vec3(c, sqrt(1.0 - r2));
}
float windowDepth(vec3 eyePoint) {
    vec4 clip = uProjection * vec4(eyePoint, 1.0);
    return clip.z / clip.w * 0.5 + 0.5;
}
)";

/// Particles mode: a lit sphere per particle.
inline constexpr const char* kParticleFragment = R"(
uniform vec3 uLightDirection;  // eye space, towards the light
out vec4 fragColor;
void main() {
    vec3 n = sphereNormal();
    vec3 p = vCentre + n * uRadius;
    gl_FragDepth = windowDepth(p);
    float diffuse = max(dot(n, uLightDirection), 0.0);
    vec3 h = normalize(uLightDirection + normalize(-p));
    float specular = pow(max(dot(n, h), 0.0), 48.0);
    fragColor = vec4(vColor * (0.35 + 0.65 * diffuse) + 0.2 * specular, 1.0);
}
)";

/// Surface mode, pass 1 (van der Laan et al. 2009 §3.1): the nearest sphere's eye distance.
inline constexpr const char* kDepthFragment = R"(
out float fragDistance;  // -z in eye space, m; the cleared 0 means "no fluid here"
void main() {
    vec3 p = vCentre + sphereNormal() * uRadius;
    gl_FragDepth = windowDepth(p);
    fragDistance = -p.z;
}
)";

/// Surface mode, pass 2 (§3.4): fluid thickness along each ray, added up over all spheres
/// with additive blending; and foam and the materials' colours (weighted by thickness),
/// added up the same way, so mixed liquids tint the surface by how much of each is seen.
inline constexpr const char* kThicknessFragment = R"(
uniform float uThicknessScale;  // sphere volume → particle volume, so sums give metres of fluid
layout(location = 0) out vec2 fragThicknessFoam;
layout(location = 1) out vec4 fragColourSum;
void main() {
    vec3 n = sphereNormal();
    float chord = 2.0 * uRadius * n.z * uThicknessScale;
    fragThicknessFoam = vec2(chord, vFoam * n.z * 0.2);
    fragColourSum = vec4(vColor * chord, chord);
}
)";

/// Surface mode, pass 3: smooth the depth so the spheres become one surface. A separable
/// bilateral Gaussian whose width follows the sprites' screen size, and which leaves out
/// samples more than a narrow depth range away (after the narrow-range filter of Truong &
/// Yuksel 2018), so silhouettes and fluid behind fluid are not blurred together. van der
/// Laan et al. 2009 use curvature flow here; the filter gives similar smoothness in fewer
/// passes.
inline constexpr const char* kSmoothFragment = R"(
uniform sampler2D uDistance;
uniform ivec2 uDirection;
uniform float uPixelRadius;  // a sphere's screen radius at 1 m, px
uniform float uDepthRange;   // m
out float fragDistance;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uDistance, 0);
    float d0 = texelFetch(uDistance, p, 0).r;
    if (d0 <= 0.0) {
        fragDistance = 0.0;
        return;
    }
    float radius = clamp(uPixelRadius / d0 * 1.5, 1.0, 16.0);
    float inverseTwoSigma2 = 1.0 / (2.0 * (0.5 * radius) * (0.5 * radius));
    int n = int(ceil(radius));
    float sum = 0.0;
    float weights = 0.0;
    for (int i = -16; i <= 16; ++i) {
        if (abs(i) > n) continue;
        float d = texelFetch(uDistance, clamp(p + i * uDirection, ivec2(0), size - 1), 0).r;
        if (d <= 0.0 || abs(d - d0) > uDepthRange) continue;
        float dz = (d - d0) / uDepthRange;
        float w = exp(-float(i * i) * inverseTwoSigma2 - 2.0 * dz * dz);
        sum += d * w;
        weights += w;
    }
    fragDistance = sum / weights;
}
)";

/// Surface mode, pass 4 (§3.3–3.5): normals from the smoothed depth, then Fresnel-weighted
/// reflection of the sky and refraction of the background, absorbed by the thickness
/// (Beer–Lambert), a sun highlight and foam.
inline constexpr const char* kCompositeFragment = R"(
uniform sampler2D uDistance;
uniform sampler2D uThicknessFoam;
uniform sampler2D uBackground;
uniform mat4 uProjection;
uniform mat4 uInverseView;
uniform vec2 uTexel;
uniform sampler2D uColourSum;
uniform float uAbsorption;    // per metre, of the colours a liquid does not have
uniform float uRefraction;    // background offset, uv per metre of thickness
uniform float uFoam;          // 1: whitecaps on, 0: off
out vec4 fragColor;
vec3 eyePoint(vec2 uv, float d) {
    vec2 ndc = uv * 2.0 - 1.0;
    return vec3(ndc.x * d / uProjection[0][0], ndc.y * d / uProjection[1][1], -d);
}
void main() {
    vec2 uv = gl_FragCoord.xy * uTexel;
    vec3 background = texture(uBackground, uv).rgb;
    float d = texture(uDistance, uv).r;
    if (d <= 0.0) {
        fragColor = vec4(background, 1.0);
        return;
    }
    vec2 thicknessFoam = texture(uThicknessFoam, uv).rg;
    vec3 p = eyePoint(uv, d);
    // Of the two one-sided differences take the one with the smaller depth step, so that a
    // silhouette does not bend the normal (van der Laan et al. 2009, §3.3).
    vec2 dx = vec2(uTexel.x, 0.0);
    vec2 dy = vec2(0.0, uTexel.y);
    float dr = texture(uDistance, uv + dx).r, dl = texture(uDistance, uv - dx).r;
    float du = texture(uDistance, uv + dy).r, dd = texture(uDistance, uv - dy).r;
    vec3 ddx = eyePoint(uv + dx, dr) - p;
    vec3 ddx2 = p - eyePoint(uv - dx, dl);
    if (dr <= 0.0 || (dl > 0.0 && abs(ddx2.z) < abs(ddx.z))) ddx = ddx2;
    vec3 ddy = eyePoint(uv + dy, du) - p;
    vec3 ddy2 = p - eyePoint(uv - dy, dd);
    if (du <= 0.0 || (dd > 0.0 && abs(ddy2.z) < abs(ddy.z))) ddy = ddy2;
    vec3 n = normalize(cross(ddx, ddy));
    vec3 v = normalize(-p);
    if (dot(n, v) < 0.0) n = -n;

    mat3 toWorld = mat3(uInverseView);
    vec3 nWorld = toWorld * n;
    vec3 vWorld = toWorld * v;
    float fresnel = 0.02 + 0.98 * pow(1.0 - max(dot(n, v), 0.0), 5.0);  // Schlick, water's F0
    vec3 reflected = skyColor(reflect(-vWorld, nWorld));

    float thickness = thicknessFoam.r;
    vec2 offset = n.xy * min(thickness * uRefraction, 0.04);
    vec3 behind = texture(uBackground, clamp(uv - offset, vec2(0.0), vec2(1.0))).rgb;
    // A liquid of colour c absorbs what it lacks (Beer–Lambert, per channel): water's default
    // blue absorbs red most, as real water does. Deep liquid shows its own colour, darkened.
    vec4 colourSum = texture(uColourSum, uv);
    vec3 tint = colourSum.a > 0.0 ? colourSum.rgb / colourSum.a : vec3(0.2, 0.45, 0.9);
    vec3 lacking = vec3(1.0) - tint;
    vec3 transmitted = exp(-uAbsorption * (lacking * lacking + 0.04) * thickness);
    vec3 deep = tint * 0.3;
    vec3 refracted = behind * transmitted + deep * (1.0 - transmitted);

    vec3 color = mix(refracted, reflected, fresnel);
    vec3 h = normalize(uSunDirection + vWorld);
    color += vec3(1.0, 0.96, 0.88) * pow(max(dot(nWorld, h), 0.0), 350.0) * 1.5;
    color = mix(color, vec3(0.93, 0.95, 0.97), clamp(thicknessFoam.g * uFoam, 0.0, 0.85));
    fragColor = vec4(color, 1.0);
}
)";

}  // namespace tide::render::shaders
