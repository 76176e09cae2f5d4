// The scene's per-vertex attributes (GpuScene, kBindingVertexAttributes): texture coordinates,
// shading normals and tangents, and how surfaces are shaded with the normals
// (docs/design.md "Shading normals"). A file of its own: a shader that declares the block counts
// it against llvmpipe's 16 storage blocks per compute shader even where it is never read.
#ifndef ISPM_VERTEX_ATTRIBUTES_GLSL
#define ISPM_VERTEX_ATTRIBUTES_GLSL
// Include after lib/scene_buffers.glsl (its triangles and instances).

layout(std430, binding = kBindingVertexAttributes) readonly buffer SceneVertexAttributes {
    GpuVertexAttributes vertexAttributes[];
};

// Whether a triangle has a shading normal at each corner (else it is flat-shaded).
bool hasShadingNormals(uvec4 t) {
    return vertexAttributes[t.x].normal.x < kNoShadingNormal &&
           vertexAttributes[t.y].normal.x < kNoShadingNormal &&
           vertexAttributes[t.z].normal.x < kNoShadingNormal;
}

// A vertex's object-space shading normal (unit; where hasShadingNormals).
vec3 getShadingNormal(uint vertex) {
    return normalize(decodeOctahedral(vertexAttributes[vertex].normal));
}

// Shading normals never let light through a surface: one that points to the other side of the
// unit geometric normal `geometric` is turned to its side, and one that vanished (corners'
// normals that cancel) is the geometric normal.
vec3 orientShadingNormal(vec3 shading, vec3 geometric) {
    float length_ = length(shading);
    if (!(length_ > 0.0)) return geometric;
    shading /= length_;
    return dot(shading, geometric) < 0.0 ? -shading : shading;
}

// The object-space normal the surface's front (the side its winding faces) has at barycentrics
// b: the corners' shading normals interpolated (not unit), or the face normal where the triangle
// is flat-shaded. Normal maps perturb it (scene_textures.glsl).
vec3 interpolateFrontNormal(uint triangle, vec2 b) {
    uvec4 t = triangles[triangle];
    if (!hasShadingNormals(t)) {
        vec3 p0 = positions[t.x].xyz;
        return cross(positions[t.y].xyz - p0, positions[t.z].xyz - p0);
    }
    return (1.0 - b.x - b.y) * getShadingNormal(t.x) + b.x * getShadingNormal(t.y) +
           b.y * getShadingNormal(t.z);
}

// The object-space tangent at barycentrics b (xyz, not unit) and its handedness (w, +-1), or w =
// 0 where a corner has none.
vec4 interpolateTangent(uint triangle, vec2 b) {
    uvec4 t = triangles[triangle];
    vec4 t0 = vertexAttributes[t.x].tangent;
    vec4 t1 = vertexAttributes[t.y].tangent;
    vec4 t2 = vertexAttributes[t.z].tangent;
    if (t0.w == 0.0 || t1.w == 0.0 || t2.w == 0.0) return vec4(0.0);
    vec3 tangent = (1.0 - b.x - b.y) * t0.xyz + b.x * t1.xyz + b.y * t2.xyz;
    return vec4(tangent, t0.w);
}

// World-space unit shading normal where triangle `triangle` of instance `instance` is hit at
// barycentrics b (as intersectTriangle reports them), on the side of `geometric` (the hit's
// geometric normal, bvh.glsl's computeHitNormal, turned to either side): the corners' normals
// interpolated, or `geometric` itself on a flat-shaded triangle.
vec3 computeShadingNormal(uint triangle, uint instance, vec2 b, vec3 geometric) {
    uvec4 t = triangles[triangle];
    if (!hasShadingNormals(t)) return geometric;
    vec3 n = (1.0 - b.x - b.y) * getShadingNormal(t.x) + b.x * getShadingNormal(t.y) +
             b.y * getShadingNormal(t.z);
    return orientShadingNormal(transpose(mat3(instances[instance].objectFromWorld)) * n,
                               geometric);
}
#endif
