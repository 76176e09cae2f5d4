// The scene's per-vertex attributes (GpuScene, kBindingVertexAttributes): texture coordinates
// and shading normals, and how surfaces are shaded with the normals
// (docs/design.md "Shading normals"). A file of its own: a shader that declares the block counts
// it against llvmpipe's 16 storage blocks per compute shader even where it is never read.
#ifndef ISPM_VERTEX_ATTRIBUTES_GLSL
#define ISPM_VERTEX_ATTRIBUTES_GLSL
// Include after lib/scene_buffers.glsl (its triangles and instances).

layout(std430, binding = kBindingVertexAttributes) readonly buffer SceneVertexAttributes {
    vec4 vertexAttributes[];
};

// Whether a triangle has a shading normal at each corner (else it is flat-shaded).
bool hasShadingNormals(uvec4 t) {
    return vertexAttributes[t.x].z < kNoShadingNormal &&
           vertexAttributes[t.y].z < kNoShadingNormal && vertexAttributes[t.z].z < kNoShadingNormal;
}

// A vertex's object-space shading normal (unit; where hasShadingNormals).
vec3 getShadingNormal(uint vertex) {
    return normalize(decodeOctahedral(vertexAttributes[vertex].zw));
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
