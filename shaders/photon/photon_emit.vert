// Photon emission, vertex stage: one vertex per photon of the light view's regular grid; the
// geometry stage does the work, so this only forwards the grid index.
flat out uint vGridIndex;

void main() { vGridIndex = uint(gl_VertexID); }
