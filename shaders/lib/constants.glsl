// Numeric constants shared by the shading code.
#ifndef ISPM_CONSTANTS_GLSL
#define ISPM_CONSTANTS_GLSL
const float kPi = 3.14159265358979;
const float kInvPi = 0.318309886183791;
const float kInvTwoPi = 0.159154943091895;
#endif
