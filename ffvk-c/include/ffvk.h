/* ffvk.h: ffvk's C API, generated from ffvk-c/src by cbindgen (tests/header.rs); do not edit.
 *
 * GL's lighting state on a context (GL's entry points, enums and errors), and ffvk's
 * pipelines on the caller's Vulkan device recording draws into the caller's command buffers.
 * Build with `pkg-config --cflags --libs ffvk` (after `make install-c`), or link with -lffvk_c
 * (libffvk_c.so.0, or libffvk_c.a, which also needs -lm -ldl -lpthread). GL enums: plain
 * uint32_t values as <GL/gl.h> spells them; this header defines those it uses unless already
 * defined. Threads: a context, a renderer, a texture and a mesh are each used by one thread at
 * a time; different objects are independent. No call submits to a queue or waits on the
 * device.
 *
 * Growing without breaking: a struct that starts with `struct_size` (set it to the struct's
 * sizeof) only grows at its end, each new field documented with its default; the library
 * accepts the size of every published version, reads only what struct_size covers and gives
 * the fields beyond it their defaults, so a program built against an older ffvk.h runs with a
 * newer library. Any other size is FFVK_ERROR_INVALID_ARGUMENT. Structs without struct_size
 * never change, and no function's signature changes: the API grows by new fields and new
 * functions. */

#ifndef FFVK_H
#define FFVK_H

#include <stdint.h>
#include <vulkan/vulkan.h>

/* GL's values for the enums this API takes and returns. */
#ifndef GL_FALSE
#define GL_FALSE 0x0000
#endif
#ifndef GL_TRUE
#define GL_TRUE 0x0001
#endif
#ifndef GL_NO_ERROR
#define GL_NO_ERROR 0x0000
#endif
#ifndef GL_INVALID_ENUM
#define GL_INVALID_ENUM 0x0500
#endif
#ifndef GL_INVALID_VALUE
#define GL_INVALID_VALUE 0x0501
#endif
#ifndef GL_INVALID_OPERATION
#define GL_INVALID_OPERATION 0x0502
#endif
#ifndef GL_OUT_OF_MEMORY
#define GL_OUT_OF_MEMORY 0x0505
#endif
#ifndef GL_CURRENT_COLOR
#define GL_CURRENT_COLOR 0x0B00
#endif
#ifndef GL_CURRENT_NORMAL
#define GL_CURRENT_NORMAL 0x0B02
#endif
#ifndef GL_CURRENT_TEXTURE_COORDS
#define GL_CURRENT_TEXTURE_COORDS 0x0B03
#endif
#ifndef GL_LIGHTING
#define GL_LIGHTING 0x0B50
#endif
#ifndef GL_LIGHT_MODEL_LOCAL_VIEWER
#define GL_LIGHT_MODEL_LOCAL_VIEWER 0x0B51
#endif
#ifndef GL_LIGHT_MODEL_TWO_SIDE
#define GL_LIGHT_MODEL_TWO_SIDE 0x0B52
#endif
#ifndef GL_LIGHT_MODEL_AMBIENT
#define GL_LIGHT_MODEL_AMBIENT 0x0B53
#endif
#ifndef GL_SHADE_MODEL
#define GL_SHADE_MODEL 0x0B54
#endif
#ifndef GL_COLOR_MATERIAL_FACE
#define GL_COLOR_MATERIAL_FACE 0x0B55
#endif
#ifndef GL_COLOR_MATERIAL_PARAMETER
#define GL_COLOR_MATERIAL_PARAMETER 0x0B56
#endif
#ifndef GL_COLOR_MATERIAL
#define GL_COLOR_MATERIAL 0x0B57
#endif
#ifndef GL_NORMALIZE
#define GL_NORMALIZE 0x0BA1
#endif
#ifndef GL_MODELVIEW_MATRIX
#define GL_MODELVIEW_MATRIX 0x0BA6
#endif
#ifndef GL_PROJECTION_MATRIX
#define GL_PROJECTION_MATRIX 0x0BA7
#endif
#ifndef GL_TEXTURE_MATRIX
#define GL_TEXTURE_MATRIX 0x0BA8
#endif
#ifndef GL_BLEND
#define GL_BLEND 0x0BE2
#endif
#ifndef GL_FOG
#define GL_FOG 0x0B60
#endif
#ifndef GL_CLIP_PLANE0
#define GL_CLIP_PLANE0 0x3000
#endif
#ifndef GL_MAX_CLIP_PLANES
#define GL_MAX_CLIP_PLANES 0x0D32
#endif
#ifndef GL_FOG_INDEX
#define GL_FOG_INDEX 0x0B61
#endif
#ifndef GL_FOG_DENSITY
#define GL_FOG_DENSITY 0x0B62
#endif
#ifndef GL_FOG_START
#define GL_FOG_START 0x0B63
#endif
#ifndef GL_FOG_END
#define GL_FOG_END 0x0B64
#endif
#ifndef GL_FOG_MODE
#define GL_FOG_MODE 0x0B65
#endif
#ifndef GL_FOG_COLOR
#define GL_FOG_COLOR 0x0B66
#endif
#ifndef GL_EXP
#define GL_EXP 0x0800
#endif
#ifndef GL_EXP2
#define GL_EXP2 0x0801
#endif
#ifndef GL_LINEAR
#define GL_LINEAR 0x2601
#endif
#ifndef GL_FOG_COORD_SRC
#define GL_FOG_COORD_SRC 0x8450
#endif
#ifndef GL_FOG_COORD
#define GL_FOG_COORD 0x8451
#endif
#ifndef GL_FRAGMENT_DEPTH
#define GL_FRAGMENT_DEPTH 0x8452
#endif
#ifndef GL_CURRENT_FOG_COORD
#define GL_CURRENT_FOG_COORD 0x8453
#endif
#ifndef GL_PERSPECTIVE_CORRECTION_HINT
#define GL_PERSPECTIVE_CORRECTION_HINT 0x0C50
#endif
#ifndef GL_POINT_SMOOTH_HINT
#define GL_POINT_SMOOTH_HINT 0x0C51
#endif
#ifndef GL_LINE_SMOOTH_HINT
#define GL_LINE_SMOOTH_HINT 0x0C52
#endif
#ifndef GL_POLYGON_SMOOTH_HINT
#define GL_POLYGON_SMOOTH_HINT 0x0C53
#endif
#ifndef GL_FOG_HINT
#define GL_FOG_HINT 0x0C54
#endif
#ifndef GL_GENERATE_MIPMAP_HINT
#define GL_GENERATE_MIPMAP_HINT 0x8192
#endif
#ifndef GL_TEXTURE_COMPRESSION_HINT
#define GL_TEXTURE_COMPRESSION_HINT 0x84EF
#endif
#ifndef GL_FRAGMENT_SHADER_DERIVATIVE_HINT
#define GL_FRAGMENT_SHADER_DERIVATIVE_HINT 0x8B8B
#endif
#ifndef GL_POINT_SIZE_MIN
#define GL_POINT_SIZE_MIN 0x8126
#endif
#ifndef GL_POINT_SIZE_MAX
#define GL_POINT_SIZE_MAX 0x8127
#endif
#ifndef GL_POINT_FADE_THRESHOLD_SIZE
#define GL_POINT_FADE_THRESHOLD_SIZE 0x8128
#endif
#ifndef GL_POINT_DISTANCE_ATTENUATION
#define GL_POINT_DISTANCE_ATTENUATION 0x8129
#endif
#ifndef GL_POINT_SPRITE
#define GL_POINT_SPRITE 0x8861
#endif
#ifndef GL_COORD_REPLACE
#define GL_COORD_REPLACE 0x8862
#endif
#ifndef GL_POINT_SPRITE_COORD_ORIGIN
#define GL_POINT_SPRITE_COORD_ORIGIN 0x8CA0
#endif
#ifndef GL_LOWER_LEFT
#define GL_LOWER_LEFT 0x8CA1
#endif
#ifndef GL_UPPER_LEFT
#define GL_UPPER_LEFT 0x8CA2
#endif
#ifndef GL_DONT_CARE
#define GL_DONT_CARE 0x1100
#endif
#ifndef GL_FASTEST
#define GL_FASTEST 0x1101
#endif
#ifndef GL_NICEST
#define GL_NICEST 0x1102
#endif
#ifndef GL_ALPHA_TEST
#define GL_ALPHA_TEST 0x0BC0
#endif
#ifndef GL_ALPHA_TEST_FUNC
#define GL_ALPHA_TEST_FUNC 0x0BC1
#endif
#ifndef GL_ALPHA_TEST_REF
#define GL_ALPHA_TEST_REF 0x0BC2
#endif
#ifndef GL_COLOR_SUM
#define GL_COLOR_SUM 0x8458
#endif
#ifndef GL_CURRENT_SECONDARY_COLOR
#define GL_CURRENT_SECONDARY_COLOR 0x8459
#endif
#ifndef GL_NEVER
#define GL_NEVER 0x0200
#endif
#ifndef GL_LESS
#define GL_LESS 0x0201
#endif
#ifndef GL_EQUAL
#define GL_EQUAL 0x0202
#endif
#ifndef GL_LEQUAL
#define GL_LEQUAL 0x0203
#endif
#ifndef GL_GREATER
#define GL_GREATER 0x0204
#endif
#ifndef GL_NOTEQUAL
#define GL_NOTEQUAL 0x0205
#endif
#ifndef GL_GEQUAL
#define GL_GEQUAL 0x0206
#endif
#ifndef GL_ALWAYS
#define GL_ALWAYS 0x0207
#endif
#ifndef GL_MAX_LIGHTS
#define GL_MAX_LIGHTS 0x0D31
#endif
#ifndef GL_TEXTURE_2D
#define GL_TEXTURE_2D 0x0DE1
#endif
#ifndef GL_TEXTURE_CUBE_MAP
#define GL_TEXTURE_CUBE_MAP 0x8513
#endif
#ifndef GL_ALPHA
#define GL_ALPHA 0x1906
#endif
#ifndef GL_RGB
#define GL_RGB 0x1907
#endif
#ifndef GL_RGBA
#define GL_RGBA 0x1908
#endif
#ifndef GL_LUMINANCE
#define GL_LUMINANCE 0x1909
#endif
#ifndef GL_LUMINANCE_ALPHA
#define GL_LUMINANCE_ALPHA 0x190A
#endif
#ifndef GL_INTENSITY
#define GL_INTENSITY 0x8049
#endif
#ifndef GL_FRONT
#define GL_FRONT 0x0404
#endif
#ifndef GL_BACK
#define GL_BACK 0x0405
#endif
#ifndef GL_FRONT_AND_BACK
#define GL_FRONT_AND_BACK 0x0408
#endif
#ifndef GL_ADD
#define GL_ADD 0x0104
#endif
#ifndef GL_AMBIENT
#define GL_AMBIENT 0x1200
#endif
#ifndef GL_DIFFUSE
#define GL_DIFFUSE 0x1201
#endif
#ifndef GL_SPECULAR
#define GL_SPECULAR 0x1202
#endif
#ifndef GL_POSITION
#define GL_POSITION 0x1203
#endif
#ifndef GL_SPOT_DIRECTION
#define GL_SPOT_DIRECTION 0x1204
#endif
#ifndef GL_SPOT_EXPONENT
#define GL_SPOT_EXPONENT 0x1205
#endif
#ifndef GL_SPOT_CUTOFF
#define GL_SPOT_CUTOFF 0x1206
#endif
#ifndef GL_CONSTANT_ATTENUATION
#define GL_CONSTANT_ATTENUATION 0x1207
#endif
#ifndef GL_LINEAR_ATTENUATION
#define GL_LINEAR_ATTENUATION 0x1208
#endif
#ifndef GL_QUADRATIC_ATTENUATION
#define GL_QUADRATIC_ATTENUATION 0x1209
#endif
#ifndef GL_EMISSION
#define GL_EMISSION 0x1600
#endif
#ifndef GL_SHININESS
#define GL_SHININESS 0x1601
#endif
#ifndef GL_AMBIENT_AND_DIFFUSE
#define GL_AMBIENT_AND_DIFFUSE 0x1602
#endif
#ifndef GL_COLOR_INDEXES
#define GL_COLOR_INDEXES 0x1603
#endif
#ifndef GL_FLAT
#define GL_FLAT 0x1D00
#endif
#ifndef GL_SMOOTH
#define GL_SMOOTH 0x1D01
#endif
#ifndef GL_REPLACE
#define GL_REPLACE 0x1E01
#endif
#ifndef GL_MODULATE
#define GL_MODULATE 0x2100
#endif
#ifndef GL_DECAL
#define GL_DECAL 0x2101
#endif
#ifndef GL_TEXTURE_ENV_MODE
#define GL_TEXTURE_ENV_MODE 0x2200
#endif
#ifndef GL_TEXTURE_ENV_COLOR
#define GL_TEXTURE_ENV_COLOR 0x2201
#endif
#ifndef GL_TEXTURE_ENV
#define GL_TEXTURE_ENV 0x2300
#endif
#ifndef GL_COMBINE
#define GL_COMBINE 0x8570
#endif
#ifndef GL_COMBINE_RGB
#define GL_COMBINE_RGB 0x8571
#endif
#ifndef GL_COMBINE_ALPHA
#define GL_COMBINE_ALPHA 0x8572
#endif
#ifndef GL_RGB_SCALE
#define GL_RGB_SCALE 0x8573
#endif
#ifndef GL_ALPHA_SCALE
#define GL_ALPHA_SCALE 0x0D1C
#endif
#ifndef GL_ADD_SIGNED
#define GL_ADD_SIGNED 0x8574
#endif
#ifndef GL_INTERPOLATE
#define GL_INTERPOLATE 0x8575
#endif
#ifndef GL_SUBTRACT
#define GL_SUBTRACT 0x84E7
#endif
#ifndef GL_DOT3_RGB
#define GL_DOT3_RGB 0x86AE
#endif
#ifndef GL_DOT3_RGBA
#define GL_DOT3_RGBA 0x86AF
#endif
#ifndef GL_TEXTURE
#define GL_TEXTURE 0x1702
#endif
#ifndef GL_CONSTANT
#define GL_CONSTANT 0x8576
#endif
#ifndef GL_PRIMARY_COLOR
#define GL_PRIMARY_COLOR 0x8577
#endif
#ifndef GL_PREVIOUS
#define GL_PREVIOUS 0x8578
#endif
#ifndef GL_TEXTURE0
#define GL_TEXTURE0 0x84C0
#endif
#ifndef GL_TEXTURE1
#define GL_TEXTURE1 0x84C1
#endif
#ifndef GL_TEXTURE2
#define GL_TEXTURE2 0x84C2
#endif
#ifndef GL_TEXTURE3
#define GL_TEXTURE3 0x84C3
#endif
#ifndef GL_ACTIVE_TEXTURE
#define GL_ACTIVE_TEXTURE 0x84E0
#endif
#ifndef GL_MAX_TEXTURE_UNITS
#define GL_MAX_TEXTURE_UNITS 0x84E2
#endif
#ifndef GL_MAX_TEXTURE_COORDS
#define GL_MAX_TEXTURE_COORDS 0x8871
#endif
#ifndef GL_SRC0_RGB
#define GL_SRC0_RGB 0x8580
#endif
#ifndef GL_SRC1_RGB
#define GL_SRC1_RGB 0x8581
#endif
#ifndef GL_SRC2_RGB
#define GL_SRC2_RGB 0x8582
#endif
#ifndef GL_SRC0_ALPHA
#define GL_SRC0_ALPHA 0x8588
#endif
#ifndef GL_SRC1_ALPHA
#define GL_SRC1_ALPHA 0x8589
#endif
#ifndef GL_SRC2_ALPHA
#define GL_SRC2_ALPHA 0x858A
#endif
#ifndef GL_OPERAND0_RGB
#define GL_OPERAND0_RGB 0x8590
#endif
#ifndef GL_OPERAND1_RGB
#define GL_OPERAND1_RGB 0x8591
#endif
#ifndef GL_OPERAND2_RGB
#define GL_OPERAND2_RGB 0x8592
#endif
#ifndef GL_OPERAND0_ALPHA
#define GL_OPERAND0_ALPHA 0x8598
#endif
#ifndef GL_OPERAND1_ALPHA
#define GL_OPERAND1_ALPHA 0x8599
#endif
#ifndef GL_OPERAND2_ALPHA
#define GL_OPERAND2_ALPHA 0x859A
#endif
#ifndef GL_S
#define GL_S 0x2000
#endif
#ifndef GL_T
#define GL_T 0x2001
#endif
#ifndef GL_R
#define GL_R 0x2002
#endif
#ifndef GL_Q
#define GL_Q 0x2003
#endif
#ifndef GL_EYE_LINEAR
#define GL_EYE_LINEAR 0x2400
#endif
#ifndef GL_OBJECT_LINEAR
#define GL_OBJECT_LINEAR 0x2401
#endif
#ifndef GL_SPHERE_MAP
#define GL_SPHERE_MAP 0x2402
#endif
#ifndef GL_TEXTURE_GEN_MODE
#define GL_TEXTURE_GEN_MODE 0x2500
#endif
#ifndef GL_OBJECT_PLANE
#define GL_OBJECT_PLANE 0x2501
#endif
#ifndef GL_EYE_PLANE
#define GL_EYE_PLANE 0x2502
#endif
#ifndef GL_NORMAL_MAP
#define GL_NORMAL_MAP 0x8511
#endif
#ifndef GL_REFLECTION_MAP
#define GL_REFLECTION_MAP 0x8512
#endif
#ifndef GL_TEXTURE_GEN_S
#define GL_TEXTURE_GEN_S 0x0C60
#endif
#ifndef GL_TEXTURE_GEN_T
#define GL_TEXTURE_GEN_T 0x0C61
#endif
#ifndef GL_TEXTURE_GEN_R
#define GL_TEXTURE_GEN_R 0x0C62
#endif
#ifndef GL_TEXTURE_GEN_Q
#define GL_TEXTURE_GEN_Q 0x0C63
#endif
#ifndef GL_LIGHT0
#define GL_LIGHT0 0x4000
#endif
#ifndef GL_LIGHT1
#define GL_LIGHT1 0x4001
#endif
#ifndef GL_LIGHT2
#define GL_LIGHT2 0x4002
#endif
#ifndef GL_LIGHT3
#define GL_LIGHT3 0x4003
#endif
#ifndef GL_LIGHT4
#define GL_LIGHT4 0x4004
#endif
#ifndef GL_LIGHT5
#define GL_LIGHT5 0x4005
#endif
#ifndef GL_LIGHT6
#define GL_LIGHT6 0x4006
#endif
#ifndef GL_LIGHT7
#define GL_LIGHT7 0x4007
#endif
#ifndef GL_RESCALE_NORMAL
#define GL_RESCALE_NORMAL 0x803A
#endif
#ifndef GL_LIGHT_MODEL_COLOR_CONTROL
#define GL_LIGHT_MODEL_COLOR_CONTROL 0x81F8
#endif
#ifndef GL_SINGLE_COLOR
#define GL_SINGLE_COLOR 0x81F9
#endif
#ifndef GL_SEPARATE_SPECULAR_COLOR
#define GL_SEPARATE_SPECULAR_COLOR 0x81FA
#endif
#ifndef GL_POINT_SIZE
#define GL_POINT_SIZE 0x0B11
#endif
#ifndef GL_LINE_WIDTH
#define GL_LINE_WIDTH 0x0B21
#endif
#ifndef GL_LINE_STIPPLE
#define GL_LINE_STIPPLE 0x0B24
#endif
#ifndef GL_POLYGON_STIPPLE
#define GL_POLYGON_STIPPLE 0x0B42
#endif
#ifndef GL_LINE_STIPPLE_PATTERN
#define GL_LINE_STIPPLE_PATTERN 0x0B25
#endif
#ifndef GL_LINE_STIPPLE_REPEAT
#define GL_LINE_STIPPLE_REPEAT 0x0B26
#endif
#ifndef GL_POLYGON_MODE
#define GL_POLYGON_MODE 0x0B40
#endif
#ifndef GL_EDGE_FLAG
#define GL_EDGE_FLAG 0x0B43
#endif
#ifndef GL_CULL_FACE
#define GL_CULL_FACE 0x0B44
#endif
#ifndef GL_CULL_FACE_MODE
#define GL_CULL_FACE_MODE 0x0B45
#endif
#ifndef GL_FRONT_FACE
#define GL_FRONT_FACE 0x0B46
#endif
#ifndef GL_DEPTH_RANGE
#define GL_DEPTH_RANGE 0x0B70
#endif
#ifndef GL_DEPTH_TEST
#define GL_DEPTH_TEST 0x0B71
#endif
#ifndef GL_DEPTH_WRITEMASK
#define GL_DEPTH_WRITEMASK 0x0B72
#endif
#ifndef GL_DEPTH_FUNC
#define GL_DEPTH_FUNC 0x0B74
#endif
#ifndef GL_STENCIL_TEST
#define GL_STENCIL_TEST 0x0B90
#endif
#ifndef GL_STENCIL_CLEAR_VALUE
#define GL_STENCIL_CLEAR_VALUE 0x0B91
#endif
#ifndef GL_STENCIL_FUNC
#define GL_STENCIL_FUNC 0x0B92
#endif
#ifndef GL_STENCIL_VALUE_MASK
#define GL_STENCIL_VALUE_MASK 0x0B93
#endif
#ifndef GL_STENCIL_FAIL
#define GL_STENCIL_FAIL 0x0B94
#endif
#ifndef GL_STENCIL_PASS_DEPTH_FAIL
#define GL_STENCIL_PASS_DEPTH_FAIL 0x0B95
#endif
#ifndef GL_STENCIL_PASS_DEPTH_PASS
#define GL_STENCIL_PASS_DEPTH_PASS 0x0B96
#endif
#ifndef GL_STENCIL_REF
#define GL_STENCIL_REF 0x0B97
#endif
#ifndef GL_STENCIL_WRITEMASK
#define GL_STENCIL_WRITEMASK 0x0B98
#endif
#ifndef GL_STENCIL_BACK_FUNC
#define GL_STENCIL_BACK_FUNC 0x8800
#endif
#ifndef GL_STENCIL_BACK_FAIL
#define GL_STENCIL_BACK_FAIL 0x8801
#endif
#ifndef GL_STENCIL_BACK_PASS_DEPTH_FAIL
#define GL_STENCIL_BACK_PASS_DEPTH_FAIL 0x8802
#endif
#ifndef GL_STENCIL_BACK_PASS_DEPTH_PASS
#define GL_STENCIL_BACK_PASS_DEPTH_PASS 0x8803
#endif
#ifndef GL_STENCIL_BACK_REF
#define GL_STENCIL_BACK_REF 0x8CA3
#endif
#ifndef GL_STENCIL_BACK_VALUE_MASK
#define GL_STENCIL_BACK_VALUE_MASK 0x8CA4
#endif
#ifndef GL_STENCIL_BACK_WRITEMASK
#define GL_STENCIL_BACK_WRITEMASK 0x8CA5
#endif
#ifndef GL_BLEND_DST
#define GL_BLEND_DST 0x0BE0
#endif
#ifndef GL_BLEND_SRC
#define GL_BLEND_SRC 0x0BE1
#endif
#ifndef GL_LOGIC_OP_MODE
#define GL_LOGIC_OP_MODE 0x0BF0
#endif
#ifndef GL_COLOR_LOGIC_OP
#define GL_COLOR_LOGIC_OP 0x0BF2
#endif
#ifndef GL_COLOR_WRITEMASK
#define GL_COLOR_WRITEMASK 0x0C23
#endif
#ifndef GL_POLYGON_OFFSET_UNITS
#define GL_POLYGON_OFFSET_UNITS 0x2A00
#endif
#ifndef GL_POLYGON_OFFSET_POINT
#define GL_POLYGON_OFFSET_POINT 0x2A01
#endif
#ifndef GL_POLYGON_OFFSET_LINE
#define GL_POLYGON_OFFSET_LINE 0x2A02
#endif
#ifndef GL_POLYGON_OFFSET_FILL
#define GL_POLYGON_OFFSET_FILL 0x8037
#endif
#ifndef GL_POLYGON_OFFSET_FACTOR
#define GL_POLYGON_OFFSET_FACTOR 0x8038
#endif
#ifndef GL_BLEND_COLOR
#define GL_BLEND_COLOR 0x8005
#endif
#ifndef GL_BLEND_EQUATION
#define GL_BLEND_EQUATION 0x8009
#endif
#ifndef GL_BLEND_EQUATION_RGB
#define GL_BLEND_EQUATION_RGB 0x8009
#endif
#ifndef GL_BLEND_EQUATION_ALPHA
#define GL_BLEND_EQUATION_ALPHA 0x883D
#endif
#ifndef GL_BLEND_DST_RGB
#define GL_BLEND_DST_RGB 0x80C8
#endif
#ifndef GL_BLEND_SRC_RGB
#define GL_BLEND_SRC_RGB 0x80C9
#endif
#ifndef GL_BLEND_DST_ALPHA
#define GL_BLEND_DST_ALPHA 0x80CA
#endif
#ifndef GL_BLEND_SRC_ALPHA
#define GL_BLEND_SRC_ALPHA 0x80CB
#endif
#ifndef GL_CW
#define GL_CW 0x0900
#endif
#ifndef GL_CCW
#define GL_CCW 0x0901
#endif
#ifndef GL_POINT
#define GL_POINT 0x1B00
#endif
#ifndef GL_LINE
#define GL_LINE 0x1B01
#endif
#ifndef GL_FILL
#define GL_FILL 0x1B02
#endif
#ifndef GL_KEEP
#define GL_KEEP 0x1E00
#endif
#ifndef GL_INCR
#define GL_INCR 0x1E02
#endif
#ifndef GL_DECR
#define GL_DECR 0x1E03
#endif
#ifndef GL_INVERT
#define GL_INVERT 0x150A
#endif
#ifndef GL_INCR_WRAP
#define GL_INCR_WRAP 0x8507
#endif
#ifndef GL_DECR_WRAP
#define GL_DECR_WRAP 0x8508
#endif
#ifndef GL_ZERO
#define GL_ZERO 0x0000
#endif
#ifndef GL_ONE
#define GL_ONE 0x0001
#endif
#ifndef GL_SRC_COLOR
#define GL_SRC_COLOR 0x0300
#endif
#ifndef GL_ONE_MINUS_SRC_COLOR
#define GL_ONE_MINUS_SRC_COLOR 0x0301
#endif
#ifndef GL_SRC_ALPHA
#define GL_SRC_ALPHA 0x0302
#endif
#ifndef GL_ONE_MINUS_SRC_ALPHA
#define GL_ONE_MINUS_SRC_ALPHA 0x0303
#endif
#ifndef GL_DST_ALPHA
#define GL_DST_ALPHA 0x0304
#endif
#ifndef GL_ONE_MINUS_DST_ALPHA
#define GL_ONE_MINUS_DST_ALPHA 0x0305
#endif
#ifndef GL_DST_COLOR
#define GL_DST_COLOR 0x0306
#endif
#ifndef GL_ONE_MINUS_DST_COLOR
#define GL_ONE_MINUS_DST_COLOR 0x0307
#endif
#ifndef GL_SRC_ALPHA_SATURATE
#define GL_SRC_ALPHA_SATURATE 0x0308
#endif
#ifndef GL_CONSTANT_COLOR
#define GL_CONSTANT_COLOR 0x8001
#endif
#ifndef GL_ONE_MINUS_CONSTANT_COLOR
#define GL_ONE_MINUS_CONSTANT_COLOR 0x8002
#endif
#ifndef GL_CONSTANT_ALPHA
#define GL_CONSTANT_ALPHA 0x8003
#endif
#ifndef GL_ONE_MINUS_CONSTANT_ALPHA
#define GL_ONE_MINUS_CONSTANT_ALPHA 0x8004
#endif
#ifndef GL_FUNC_ADD
#define GL_FUNC_ADD 0x8006
#endif
#ifndef GL_MIN
#define GL_MIN 0x8007
#endif
#ifndef GL_MAX
#define GL_MAX 0x8008
#endif
#ifndef GL_FUNC_SUBTRACT
#define GL_FUNC_SUBTRACT 0x800A
#endif
#ifndef GL_FUNC_REVERSE_SUBTRACT
#define GL_FUNC_REVERSE_SUBTRACT 0x800B
#endif
#ifndef GL_CLEAR
#define GL_CLEAR 0x1500
#endif
#ifndef GL_AND
#define GL_AND 0x1501
#endif
#ifndef GL_AND_REVERSE
#define GL_AND_REVERSE 0x1502
#endif
#ifndef GL_COPY
#define GL_COPY 0x1503
#endif
#ifndef GL_AND_INVERTED
#define GL_AND_INVERTED 0x1504
#endif
#ifndef GL_NOOP
#define GL_NOOP 0x1505
#endif
#ifndef GL_XOR
#define GL_XOR 0x1506
#endif
#ifndef GL_OR
#define GL_OR 0x1507
#endif
#ifndef GL_NOR
#define GL_NOR 0x1508
#endif
#ifndef GL_EQUIV
#define GL_EQUIV 0x1509
#endif
#ifndef GL_OR_REVERSE
#define GL_OR_REVERSE 0x150B
#endif
#ifndef GL_COPY_INVERTED
#define GL_COPY_INVERTED 0x150C
#endif
#ifndef GL_OR_INVERTED
#define GL_OR_INVERTED 0x150D
#endif
#ifndef GL_NAND
#define GL_NAND 0x150E
#endif
#ifndef GL_SET
#define GL_SET 0x150F
#endif
#ifndef GL_POINTS
#define GL_POINTS 0x0000
#endif
#ifndef GL_LINES
#define GL_LINES 0x0001
#endif
#ifndef GL_LINE_LOOP
#define GL_LINE_LOOP 0x0002
#endif
#ifndef GL_LINE_STRIP
#define GL_LINE_STRIP 0x0003
#endif
#ifndef GL_TRIANGLES
#define GL_TRIANGLES 0x0004
#endif
#ifndef GL_TRIANGLE_STRIP
#define GL_TRIANGLE_STRIP 0x0005
#endif
#ifndef GL_TRIANGLE_FAN
#define GL_TRIANGLE_FAN 0x0006
#endif
#ifndef GL_QUADS
#define GL_QUADS 0x0007
#endif
#ifndef GL_QUAD_STRIP
#define GL_QUAD_STRIP 0x0008
#endif
#ifndef GL_POLYGON
#define GL_POLYGON 0x0009
#endif
#ifndef GL_TRIANGLES_ADJACENCY
#define GL_TRIANGLES_ADJACENCY 0x000C
#endif


/*
 The most `frames_in_flight` a renderer takes (`ffvk::MAX_FRAMES_IN_FLIGHT`).
 */
#define FFVK_MAX_FRAMES_IN_FLIGHT 64

/*
 The most vertex `bindings` a renderer takes (`ffvk::MAX_VERTEX_BINDINGS`).
 */
#define FFVK_MAX_VERTEX_BINDINGS 32

/*
 `dynamicRendering` (Vulkan 1.3): required.
 */
#define FFVK_FEATURE_DYNAMIC_RENDERING 1

/*
 `VK_EXT_provoking_vertex` with `provokingVertexLast`: needed for `GL_FLAT`.
 */
#define FFVK_FEATURE_PROVOKING_VERTEX_LAST 2

/*
 `wideLines`: needed for a line width other than 1.
 */
#define FFVK_FEATURE_WIDE_LINES 4

/*
 `largePoints`: needed for a point size other than 1.
 */
#define FFVK_FEATURE_LARGE_POINTS 8

/*
 `shaderClipDistance`: needed for GL's user clip planes (`ffvkClipPlane`).
 */
#define FFVK_FEATURE_CLIP_DISTANCE 16

/*
 `VkPhysicalDeviceFeatures::fillModeNonSolid`: needed for `ffvkPolygonMode`'s `GL_LINE` and
 `GL_POINT`.
 */
#define FFVK_FEATURE_FILL_MODE_NON_SOLID 32

/*
 `VkPhysicalDeviceFeatures::logicOp`: needed for `GL_COLOR_LOGIC_OP` (`ffvkLogicOp`).
 */
#define FFVK_FEATURE_LOGIC_OP 64

/*
 The extension `VK_EXT_line_rasterization` enabled with
 `VkPhysicalDeviceLineRasterizationFeaturesEXT::bresenhamLines` and
 `stippledBresenhamLines`: needed for `GL_LINE_STIPPLE` (`ffvkLineStipple`). With it every
 line and polygon outline is drawn as GL's aliased (diamond-exit) lines.
 */
#define FFVK_FEATURE_STIPPLED_LINES 128

/*
 `VkPhysicalDeviceFeatures::geometryShader` and `shaderTessellationAndGeometryPointSize`:
 needed for GL's edge flags (draws of mode `GL_TRIANGLES_ADJACENCY` from
 `ffvkEdgeFlaggedIndices`).
 */
#define FFVK_FEATURE_GEOMETRY_SHADER 256

/*
 The extension `VK_EXT_non_seamless_cube_map` enabled with
 `VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT::nonSeamlessCubeMap`: lets the caller's cube
 map samplers (`ffvkCreateCubeMap`) take `VK_SAMPLER_CREATE_NON_SEAMLESS_CUBE_MAP_BIT_EXT`,
 filtering each face on its own as GL 2.1 does. ffvk makes no sampler of the caller's: the
 bit says what the device has, and no draw is refused without it.
 */
#define FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP 512

/*
 `FfvkDrawInfo::raster_source`: the draw's raster state is its `raster` (the default).
 */
#define FFVK_RASTER_SOURCE_DRAW 0

/*
 `FfvkDrawInfo::raster_source`: the draw's raster state is the context's GL raster state at
 `ffvkDraw` (`ffvkPolygonMode`, `ffvkStencilFunc`, `ffvkColorMask`, `ffvkEnable`, ...).
 */
#define FFVK_RASTER_SOURCE_CONTEXT 1

/*
 The most extension names `ffvkDeviceRequirements` ever lists, in this version and later
 ones: room for this many is always enough.
 */
#define FFVK_MAX_DEVICE_EXTENSIONS 4

/*
 What an `FfvkResult`-returning entry point reports. Every code but `FFVK_SUCCESS` comes
 with a message, `ffvkResultMessage()`, naming what failed and what was expected.
 */
typedef enum FfvkResult {
  /*
   It worked.
   */
  FFVK_SUCCESS = 0,
  /*
   A null pointer, a wrong `struct_size`, a value out of range or a call out of order
   (e.g. `ffvkDraw` outside `ffvkBeginDraws` … `ffvkEndDraws`). Nothing changed.
   */
  FFVK_ERROR_INVALID_ARGUMENT = -1,
  /*
   The device lacks something ffvk needs (Vulkan 1.3, dynamic rendering, a feature the
   caller said it enabled), or the caller did not enable it.
   */
  FFVK_ERROR_MISSING_FEATURE = -2,
  /*
   Host or device memory ran out.
   */
  FFVK_ERROR_OUT_OF_MEMORY = -3,
  /*
   A Vulkan call failed (the message names it and its `VkResult`), or the device was lost.
   */
  FFVK_ERROR_VULKAN = -4,
  /*
   The context's GL state cannot be drawn (e.g. a soft spot edge wider than its cutoff, a
   modelview that cannot be inverted): the message names the parameter and value.
   */
  FFVK_ERROR_STATE = -5,
  /*
   An internal error (a panic inside ffvk, caught at the boundary). The object it
   happened on should be destroyed.
   */
  FFVK_ERROR_INTERNAL = -6,
} FfvkResult;

/*
 GL's lighting state, its matrices and its error flag: what an application's GL calls set.
 Made by `ffvkCreateContext`, freed by `ffvkDestroyContext`. One thread at a time may call
 into a context (GL's rule for a current context); different contexts are independent.
 */
typedef struct FfvkContext FfvkContext;

/*
 A host mesh made by ffvk (`ffvkCreateTeapot`): arrays the caller copies into its buffers.
 */
typedef struct FfvkMesh FfvkMesh;

/*
 ffvk on the caller's device (`ffvkCreateRenderer`).
 */
typedef struct FfvkRenderer FfvkRenderer;

/*
 A descriptor set naming the caller's image view and sampler: a 2D texture
 (`ffvkCreateTexture`) or a cube map (`ffvkCreateCubeMap`).
 */
typedef struct FfvkTexture FfvkTexture;

/*
 A vertex layout of one renderer (`ffvkCreateVertexLayout`), named by `FfvkDrawInfo::layout`.
 */
typedef struct FfvkVertexLayout FfvkVertexLayout;

/*
 A view of an `FfvkMesh`'s arrays, valid until `ffvkDestroyMesh`. It never changes (it has
 no `struct_size`).
 */
typedef struct FfvkMeshArrays {
  /*
   How many vertices.
   */
  uint32_t vertex_count;
  /*
   `vertex_count` object-space positions, x y z.
   */
  const float *positions;
  /*
   `vertex_count` normals, x y z.
   */
  const float *normals;
  /*
   `vertex_count` colors, r g b a in [0, 1].
   */
  const float *colors;
  /*
   How many indices.
   */
  uint32_t index_count;
  /*
   `index_count` indices: counter-clockwise triangles (`GL_TRIANGLES`).
   */
  const uint32_t *indices;
} FfvkMeshArrays;

/*
 Where one vertex attribute lives: a binding of the create info's `bindings`, the byte
 offset within one element, the format (any the shaders read as floats, e.g.
 `VK_FORMAT_R32G32B32_SFLOAT`, `VK_FORMAT_R8G8B8A8_UNORM`, that the device reads from
 vertex buffers). The attribute lies within one element: offset + the format's size <= the
 binding's stride.

 It never changes (it has no `struct_size`).
 */
typedef struct FfvkAttribute {
  /*
   The vertex buffer binding it is read from.
   */
  uint32_t binding;
  /*
   Byte offset within one element of that binding.
   */
  uint32_t offset;
  /*
   The attribute's format.
   */
  VkFormat format;
} FfvkAttribute;

/*
 What `ffvkCreateRenderer` takes. Set `struct_size` to `sizeof(FfvkRendererCreateInfo)`.

 How it grows (the rule of every struct with a `struct_size`): a later `ffvk.h` only appends
 fields, each documented with its default. The library accepts the `sizeof` of every
 published version of the struct (this header's is version 1), reads only the bytes
 `struct_size` covers and gives the fields beyond them their defaults, so a program built
 against an older header runs unchanged with a newer library. Any other size (0, between
 two versions, or a newer header's than the library knows) is refused with
 `FFVK_ERROR_INVALID_ARGUMENT`, the message naming the size given and the sizes accepted.
 */
typedef struct FfvkRendererCreateInfo {
  /*
   `sizeof(FfvkRendererCreateInfo)`.
   */
  uint32_t struct_size;
  /*
   The caller's loader entry point: ffvk loads every Vulkan function through it.
   */
  PFN_vkGetInstanceProcAddr get_instance_proc_addr;
  /*
   The caller's instance, created with `apiVersion` 1.3 or later.
   */
  VkInstance instance;
  /*
   The physical device `device` was made from.
   */
  VkPhysicalDevice physical_device;
  /*
   The caller's device: ffvk creates its objects on it and never destroys it.
   */
  VkDevice device;
  /*
   `FFVK_FEATURE_*` bits: the features the caller enabled on `device` (Vulkan cannot be
   asked). `FFVK_FEATURE_DYNAMIC_RENDERING` is required: `VkPhysicalDeviceVulkan13Features::
   dynamicRendering`. `FFVK_FEATURE_PROVOKING_VERTEX_LAST` is the extension
   `VK_EXT_provoking_vertex` enabled with `VkPhysicalDeviceProvokingVertexFeaturesEXT::
   provokingVertexLast`; without it `GL_FLAT` draws are refused. `FFVK_FEATURE_WIDE_LINES`
   and `FFVK_FEATURE_LARGE_POINTS` are `VkPhysicalDeviceFeatures::wideLines` and
   `largePoints`; `FFVK_FEATURE_CLIP_DISTANCE` is `shaderClipDistance` (draws with a user
   clip plane enabled); `FFVK_FEATURE_FILL_MODE_NON_SOLID` is `fillModeNonSolid` (polygon
   modes `GL_LINE` and `GL_POINT`); `FFVK_FEATURE_LOGIC_OP` is `logicOp`
   (`GL_COLOR_LOGIC_OP`); `FFVK_FEATURE_STIPPLED_LINES` is the extension
   `VK_EXT_line_rasterization` enabled with `VkPhysicalDeviceLineRasterizationFeaturesEXT::
   bresenhamLines` and `stippledBresenhamLines` (`GL_LINE_STIPPLE`; every line then drawn
   as GL's aliased lines); `FFVK_FEATURE_GEOMETRY_SHADER` is `geometryShader` (GL's edge
   flags: draws of mode `GL_TRIANGLES_ADJACENCY`); `FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP` is the
   extension `VK_EXT_non_seamless_cube_map` enabled with `nonSeamlessCubeMap` (the caller's
   cube map samplers may then filter each face on its own, as GL 2.1). A draw needing a
   feature not declared is refused, naming its bit.
   `ffvkDeviceRequirements` says which bits a device will have.
   */
  uint32_t enabled_features;
  /*
   The color attachment's format: an uncompressed core format the shaders write as floats
   (UNORM, SNORM, SRGB or FLOAT; not UNDEFINED, a depth or an integer format) that the
   device supports as `VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT`.
   */
  VkFormat color_format;
  /*
   The depth attachment's format, or `VK_FORMAT_UNDEFINED` for none: one of the six `D*`
   formats, supported by the device as `VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT`.
   */
  VkFormat depth_format;
  /*
   Samples per pixel of both attachments: one `VK_SAMPLE_COUNT_*_BIT`, among the device's
   `framebufferColorSampleCounts` (and `framebufferDepthSampleCounts` with a depth format,
   `framebufferStencilSampleCounts` with a stencil one).
   */
  VkSampleCountFlagBits samples;
  /*
   The caller's vertex buffer bindings (per-vertex rate), in the order draws pass their
   buffers.
   */
  const VkVertexInputBindingDescription *bindings;
  /*
   How many `bindings`, at most `FFVK_MAX_VERTEX_BINDINGS`.
   */
  uint32_t binding_count;
  /*
   Object-space position (`glVertexPointer`).
   */
  struct FfvkAttribute position;
  /*
   Object-space normal (`glNormalPointer`).
   */
  struct FfvkAttribute normal;
  /*
   Per-vertex color (`glColorPointer`), or null: every vertex takes the context's current
   color (`ffvkColor4f`).
   */
  const struct FfvkAttribute *color;
  /*
   Texture coordinates (`glTexCoordPointer`), or null: every vertex of a textured draw takes
   the context's current texture coordinates (`ffvkTexCoord4f`).
   */
  const struct FfvkAttribute *texcoord;
  /*
   Frame slots, 1 to `FFVK_MAX_FRAMES_IN_FLIGHT`: how many frames the caller records
   before it waits for the oldest.
   */
  uint32_t frames_in_flight;
  /*
   The descriptor set index of ffvk's state block (ffvk uses it and the next two).
   */
  uint32_t set_index;
  /*
   The caller's pipeline cache, or `VK_NULL_HANDLE` for ffvk's own.
   */
  VkPipelineCache pipeline_cache;
} FfvkRendererCreateInfo;

/*
 A draw's fixed-function raster state (GL's glCullFace/glFrontFace, depth and blend state,
 glPointSize, glLineWidth) in Vulkan's terms. `ffvkRasterDefaults` fills GL's initial
 values; a zeroed struct is not GL's defaults (depth writes off, depth compare NEVER, sizes
 0, which draws refuse). `ffvkDraw` refuses (`FFVK_ERROR_INVALID_ARGUMENT`, naming the field
 and value) any other value than these: `cull_mode` bits of `VK_CULL_MODE_FRONT_AND_BACK`,
 `front_face` 0 or 1, `depth_compare` `VK_COMPARE_OP_NEVER` .. `ALWAYS` (0 .. 7), and while
 blending, factors `VK_BLEND_FACTOR_ZERO` .. `SRC_ALPHA_SATURATE` (0 .. 14; no dual-source
 factors) and equations `VK_BLEND_OP_ADD` .. `MAX` (0 .. 4).

 It never changes size (`ffvkRasterDefaults` writes it whole, and it lies inside
 `FfvkDrawInfo`): raster state added later becomes new fields at the end of `FfvkDrawInfo`.
 */
typedef struct FfvkRaster {
  /*
   `GL_CULL_FACE` with glCullFace: `VK_CULL_MODE_NONE` (GL's default) or a face.
   */
  VkCullModeFlags cull_mode;
  /*
   glFrontFace: `VK_FRONT_FACE_COUNTER_CLOCKWISE` is GL's `GL_CCW` (the default).
   */
  VkFrontFace front_face;
  /*
   `GL_DEPTH_TEST` (needs a depth format).
   */
  uint8_t depth_test;
  /*
   glDepthMask (GL's default: true; only while the depth test is on).
   */
  uint8_t depth_write;
  /*
   glDepthFunc (GL's default: `VK_COMPARE_OP_LESS`).
   */
  VkCompareOp depth_compare;
  /*
   `GL_BLEND`; the factors and equations below apply when it is non-zero.
   */
  uint8_t blend;
  /*
   Source factor for RGB.
   */
  VkBlendFactor src_color;
  /*
   Destination factor for RGB.
   */
  VkBlendFactor dst_color;
  /*
   Equation for RGB.
   */
  VkBlendOp color_op;
  /*
   Source factor for alpha.
   */
  VkBlendFactor src_alpha;
  /*
   Destination factor for alpha.
   */
  VkBlendFactor dst_alpha;
  /*
   Equation for alpha.
   */
  VkBlendOp alpha_op;
  /*
   glPointSize, in pixels (1 by default; another size needs `FFVK_FEATURE_LARGE_POINTS`).
   */
  float point_size;
  /*
   glLineWidth, in pixels (1 by default; another width needs `FFVK_FEATURE_WIDE_LINES`).
   */
  float line_width;
} FfvkRaster;

/*
 One draw: `glDrawArrays` (no index buffer) or `glDrawElementsBaseVertex`. Set
 `struct_size` to `sizeof(FfvkDrawInfo)`.

 It grows as `FfvkRendererCreateInfo` does: later headers append fields (each with its
 default), the library accepts every published version's size (this header's is version 5:
 version 2 appended `layout`, version 3 `raster_source`, version 4 `texture1` ..
 `texture3`, version 5 `cube_map` .. `cube_map3`) and reads only what `struct_size` covers. `raster` never grows (`FfvkRaster`
 keeps its size): the rest of GL's raster state comes from the context (`raster_source`).
 */
typedef struct FfvkDrawInfo {
  /*
   `sizeof(FfvkDrawInfo)`.
   */
  uint32_t struct_size;
  /*
   `GL_POINTS`, `GL_LINES`, `GL_LINE_STRIP`, `GL_TRIANGLES`, `GL_TRIANGLE_STRIP` or
   `GL_TRIANGLE_FAN`; `ffvkPrimitiveIndices` turns `GL_LINE_LOOP`, `GL_QUADS`,
   `GL_QUAD_STRIP` and `GL_POLYGON` into lists of these. `GL_TRIANGLES_ADJACENCY` draws
   GL's polygons with their edge flags as `ffvkEdgeFlaggedIndices` makes them (six indices
   a triangle: `first` and `count` multiples of 6; `FFVK_FEATURE_GEOMETRY_SHADER`).
   */
  uint32_t mode;
  /*
   The vertex buffers, one per binding of the create info, in its order.
   */
  const VkBuffer *vertex_buffers;
  /*
   Their byte offsets, or null for all 0.
   */
  const VkDeviceSize *vertex_offsets;
  /*
   How many `vertex_buffers`: the create info's `binding_count`.
   */
  uint32_t vertex_buffer_count;
  /*
   The index buffer, or `VK_NULL_HANDLE` to draw `count` consecutive vertices.
   */
  VkBuffer index_buffer;
  /*
   Byte offset of index 0 in `index_buffer`.
   */
  VkDeviceSize index_offset;
  /*
   `VK_INDEX_TYPE_UINT16` or `VK_INDEX_TYPE_UINT32`.
   */
  VkIndexType index_type;
  /*
   The first index (indexed) or vertex (glDrawArrays' `first`).
   */
  uint32_t first;
  /*
   How many indices or vertices.
   */
  uint32_t count;
  /*
   Added to every index before its vertex is fetched (indexed only).
   */
  int32_t vertex_offset;
  /*
   Indexed strips and fans: the index of all ones starts a new primitive.
   */
  uint8_t primitive_restart;
  /*
   The raster state.
   */
  struct FfvkRaster raster;
  /*
   Texture unit 0's texture (`GL_TEXTURE0`'s glBindTexture), sampled while unit 0's
   `GL_TEXTURE_2D` is enabled, or null (GL's texture object 0: the unit textures nothing).
   */
  const struct FfvkTexture *texture;
  /*
   Version 2: the vertex layout the buffers follow (`ffvkCreateVertexLayout`), or null
   (the default, and what a version 1 caller gets): the create info's.
   */
  const struct FfvkVertexLayout *layout;
  /*
   Version 3: where the draw's raster state comes from. `FFVK_RASTER_SOURCE_DRAW` (0, the
   default, and what version 1 and 2 callers get): `raster`. `FFVK_RASTER_SOURCE_CONTEXT`
   (1): the whole of the context's GL raster state as it is at this `ffvkDraw` (polygon
   modes and offset, line stipple, point size, line width, culling, front face, the
   stencil and depth tests, blending, blend color, logic op, color and depth masks);
   `raster` is not read.
   */
  uint32_t raster_source;
  /*
   Version 4: texture unit 1's texture (`GL_TEXTURE1`'s glBindTexture), sampled while unit
   1's `GL_TEXTURE_2D` is enabled (`ffvkActiveTexture(ctx, GL_TEXTURE1)`, `ffvkEnable`), or
   null (the default, and what version 1 to 3 callers get): unit 1 textures nothing, as
   GL's texture object 0. Its coordinates are the layout's `texcoord1`, or unit 1's current
   ones. The units apply in order, each to the result of the one before it; a
   `GL_COMBINE` source `GL_TEXTUREn` reads unit n's texel.
   */
  const struct FfvkTexture *texture1;
  /*
   Version 4: unit 2's texture, as `texture1` (null by default).
   */
  const struct FfvkTexture *texture2;
  /*
   Version 4: unit 3's texture, as `texture1` (null by default).
   */
  const struct FfvkTexture *texture3;
  /*
   Version 5: unit 0's cube map (`GL_TEXTURE0`'s glBindTexture(GL_TEXTURE_CUBE_MAP, …)),
   from `ffvkCreateCubeMap`, or null (the default, and what version 1 to 4 callers get).
   While the unit's `GL_TEXTURE_CUBE_MAP` is enabled it takes precedence over
   `GL_TEXTURE_2D` (GL 2.1 §3.8.15): the unit samples this cube map at its (s, t, r), or
   with none textures nothing, whatever `texture` holds. A 2D texture here, or a cube map in
   a `texture*` field, is `FFVK_ERROR_INVALID_ARGUMENT` naming the field and the unit.
   */
  const struct FfvkTexture *cube_map;
  /*
   Version 5: unit 1's cube map, as `cube_map` (null by default).
   */
  const struct FfvkTexture *cube_map1;
  /*
   Version 5: unit 2's cube map, as `cube_map` (null by default).
   */
  const struct FfvkTexture *cube_map2;
  /*
   Version 5: unit 3's cube map, as `cube_map` (null by default).
   */
  const struct FfvkTexture *cube_map3;
} FfvkDrawInfo;

/*
 One material parameter given per vertex (Mesa's material attributes: `glMaterial` between
 `glBegin` and `glEnd`): `face` `GL_FRONT`, `GL_BACK` or `GL_FRONT_AND_BACK`; `pname`
 `GL_AMBIENT`, `GL_DIFFUSE`, `GL_SPECULAR`, `GL_EMISSION` (RGBA,
 `VK_FORMAT_R32G32B32A32_SFLOAT`) or `GL_SHININESS` (`VK_FORMAT_R32_SFLOAT`).
 */
typedef struct FfvkMaterialAttribute {
  /*
   `GL_FRONT`, `GL_BACK` or `GL_FRONT_AND_BACK`.
   */
  uint32_t face;
  /*
   `GL_AMBIENT`, `GL_DIFFUSE`, `GL_SPECULAR`, `GL_EMISSION` or `GL_SHININESS`.
   */
  uint32_t pname;
  /*
   Where it lives in the layout's bindings.
   */
  struct FfvkAttribute attribute;
} FfvkMaterialAttribute;

/*
 What `ffvkCreateVertexLayout` takes: a layout of GL's arrays. Set `struct_size` to
 `sizeof(FfvkVertexLayoutInfo)` (the struct grows as `FfvkDrawInfo` does: later versions
 append fields and read only what the caller's size covers; this header's is version 2,
 which appended `texcoord1` .. `texcoord3`, the arrays of the texture units past the first,
 which glClientActiveTexture selects in GL). Formats are GL's: positions 2 to 4 floats or
 `GL_SHORT`s (`R16G16_SSCALED`..), normals 3 floats or `GL_BYTE`s or
 `GL_SHORT`s (`R8G8B8_SNORM`, `R16G16B16_SNORM`, or their four-component forms with padding),
 colors 3 or 4 floats, signed or unsigned bytes or shorts, or `B8G8R8A8_UNORM`
 (`GL_BGRA`), texture coordinates 1 to 4 floats or shorts. Signed normalized normals and
 colors convert as GL 2.1 says, (2c + 1)/(2^b − 1), not as Vulkan's SNORM.
 */
typedef struct FfvkVertexLayoutInfo {
  /*
   `sizeof(FfvkVertexLayoutInfo)`.
   */
  uint32_t struct_size;
  /*
   The vertex buffer bindings (per-vertex rate), in the order draws pass their buffers.
   */
  const VkVertexInputBindingDescription *bindings;
  /*
   How many `bindings`, at most `FFVK_MAX_VERTEX_BINDINGS`.
   */
  uint32_t binding_count;
  /*
   Object-space position (`glVertexPointer`).
   */
  struct FfvkAttribute position;
  /*
   Normals (`glNormalPointer`), or null: every vertex takes the context's current normal
   (`ffvkNormal3f`).
   */
  const struct FfvkAttribute *normal;
  /*
   Colors (`glColorPointer`), or null: the context's current color (`ffvkColor4f`).
   */
  const struct FfvkAttribute *color;
  /*
   Texture coordinates (`glTexCoordPointer`), or null: the context's current ones
   (`ffvkTexCoord4f`).
   */
  const struct FfvkAttribute *texcoord;
  /*
   Secondary colors (`glSecondaryColorPointer`, three components), or null: the context's
   current secondary color (`ffvkSecondaryColor3f`); summed with lighting off under
   `GL_COLOR_SUM`.
   */
  const struct FfvkAttribute *secondary_color;
  /*
   Fog coordinates (`glFogCoordPointer`, one float: `VK_FORMAT_R32_SFLOAT`), or null: the
   context's current fog coordinate (`ffvkFogCoordf`).
   */
  const struct FfvkAttribute *fog_coord;
  /*
   Material parameters given per vertex, or null with `material_count` 0. Drawn in the
   vertex and flat modes; a draw lit per fragment with such a layout is refused.
   */
  const struct FfvkMaterialAttribute *materials;
  /*
   How many `materials` (at most 10: five parameters, two faces).
   */
  uint32_t material_count;
  /*
   Version 2: texture unit 1's coordinates (glClientActiveTexture(`GL_TEXTURE1`) then
   glTexCoordPointer), or null (the default, and what a version 1 caller gets): every
   vertex takes unit 1's current coordinates (`ffvkMultiTexCoord4f(GL_TEXTURE1, …)`). Read
   while unit 1 textures (its `GL_TEXTURE_2D` enabled with a texture in
   `FfvkDrawInfo::texture1`), through unit 1's texture matrix and coordinate generation.
   `texcoord` is unit 0's.
   */
  const struct FfvkAttribute *texcoord1;
  /*
   Version 2: unit 2's coordinates, as `texcoord1` (null by default: unit 2's current ones).
   */
  const struct FfvkAttribute *texcoord2;
  /*
   Version 2: unit 3's coordinates, as `texcoord1` (null by default: unit 3's current ones).
   */
  const struct FfvkAttribute *texcoord3;
} FfvkVertexLayoutInfo;

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

/*
 glClipPlane: the plane's equation (four doubles, in object coordinates), stored in eye
 space by the inverse of the context's modelview now (GL 2.1 §2.12); enable it with
 `ffvkEnable(ctx, GL_CLIP_PLANEi)`. Drawing with a plane enabled needs
 `FFVK_FEATURE_CLIP_DISTANCE`. `plane` is GL's enum, `GL_CLIP_PLANE0` + i (i < 6), not the
 index. Errors: `GL_INVALID_ENUM` for another `plane`;
 `GL_INVALID_VALUE` for a null `equation`, a value that is not finite, or a singular
 modelview (ffvk's choices: GL leaves those undefined).

 # Safety

 `ctx` is null or a live context used by one thread at a time; `equation` is null or points
 at four doubles.
 */
void ffvkClipPlane(struct FfvkContext *ctx, uint32_t plane, const double *equation);

/*
 Creates a context in GL's initial state (table 2.10 and friends): lighting off, every
 light at its default, identity matrices, `GL_SMOOTH`, no error. Returns null only when
 memory runs out (see `ffvkResultMessage`). Free it with `ffvkDestroyContext`.
 */
struct FfvkContext *ffvkCreateContext(void);

/*
 Frees a context from `ffvkCreateContext`; null is ignored. A renderer that recorded draws
 from it no longer needs it once `ffvkEndDraws` returned.

 # Safety

 `ctx` is null or a context from `ffvkCreateContext` not yet destroyed, and no other
 thread uses it.
 */
void ffvkDestroyContext(struct FfvkContext *ctx);

/*
 glGetError: the first error recorded since the last call (GL's first error sticks; later
 ones are dropped), then `GL_NO_ERROR` until the next. A null context gives `GL_NO_ERROR`.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
uint32_t ffvkGetError(struct FfvkContext *ctx);

/*
 glEnable for `GL_LIGHTING`, `GL_LIGHTi` (i < 16), `GL_COLOR_MATERIAL`, `GL_NORMALIZE`,
 `GL_RESCALE_NORMAL`, `GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP`, `GL_COLOR_SUM`, `GL_FOG`,
 `GL_ALPHA_TEST`, `GL_CLIP_PLANEi` (i < 6), `GL_POINT_SPRITE`, `GL_TEXTURE_GEN_S`, `_T`, `_R`,
 `_Q` (the coordinate generated as `ffvkTexGeni` says, GL 2.1 §2.11.4; `GL_TEXTURE_2D`,
 `GL_TEXTURE_CUBE_MAP` and `GL_TEXTURE_GEN_*` are the active unit's, `ffvkActiveTexture`;
 with `GL_TEXTURE_CUBE_MAP` on, the unit samples the draw's cube map for it, `FfvkDrawInfo::
 cube_map`, and not its 2D texture, GL 2.1 §3.8.15), and the raster state's
 `GL_POLYGON_OFFSET_FILL`, `GL_POLYGON_OFFSET_LINE`, `GL_POLYGON_OFFSET_POINT`,
 `GL_LINE_STIPPLE`, `GL_POLYGON_STIPPLE`, `GL_STENCIL_TEST`,
 `GL_COLOR_LOGIC_OP`, `GL_BLEND`, `GL_DEPTH_TEST` and `GL_CULL_FACE` (which a draw takes with
 `FFVK_RASTER_SOURCE_CONTEXT`). Sets `GL_INVALID_ENUM` for any other cap (a layer keeps the
 rest of GL's capabilities itself). Enabling `GL_COLOR_MATERIAL` writes the
 current color into the tracked material parameters, as GL does.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkEnable(struct FfvkContext *ctx, uint32_t cap_enum);

/*
 glDisable for the caps of `ffvkEnable`; `GL_INVALID_ENUM` for any other.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkDisable(struct FfvkContext *ctx, uint32_t cap_enum);

/*
 glIsEnabled for the caps of `ffvkEnable`: `GL_TRUE` or `GL_FALSE`; `GL_INVALID_ENUM`
 (and `GL_FALSE`) for any other.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
uint8_t ffvkIsEnabled(struct FfvkContext *ctx, uint32_t cap_enum);

/*
 glLightfv: one parameter of `GL_LIGHTi`. `GL_POSITION` is transformed by the context's
 modelview (`ffvkLoadModelview`) and `GL_SPOT_DIRECTION` by its upper 3x3 at this call,
 and stored in eye space, as GL does. Errors: `GL_INVALID_ENUM` for a light past
 `GL_MAX_LIGHTS` (16) or an unknown `pname`; `GL_INVALID_VALUE` for a spot exponent
 outside [0, 128], a cutoff outside [0, 90] and not 180, a negative attenuation, a value
 that is not finite (ffvk's choice where GL leaves it unspecified) or a null `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or points
 at as many values as `pname` has (4, 3 for `GL_SPOT_DIRECTION`, 1).
 */
void ffvkLightfv(struct FfvkContext *ctx, uint32_t light, uint32_t pname, const float *params);

/*
 glLightiv: `ffvkLightfv` with integers; colors map [-2^31, 2^31 - 1] onto [-1, 1]
 (GL 2.1 table 2.9), other values convert directly.

 # Safety

 As `ffvkLightfv`.
 */
void ffvkLightiv(struct FfvkContext *ctx, uint32_t light, uint32_t pname, const int32_t *params);

/*
 glLightf: the single-valued parameters only (`GL_SPOT_EXPONENT`, `GL_SPOT_CUTOFF`,
 `GL_*_ATTENUATION`); any other `pname` sets `GL_INVALID_ENUM`. Errors as `ffvkLightfv`.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkLightf(struct FfvkContext *ctx, uint32_t light, uint32_t pname, float param);

/*
 glLighti: `ffvkLightf` with an integer.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkLighti(struct FfvkContext *ctx, uint32_t light, uint32_t pname, int32_t param);

/*
 glMaterialfv on `GL_FRONT`, `GL_BACK` or `GL_FRONT_AND_BACK`. While `GL_COLOR_MATERIAL`
 is enabled the parameters it makes track the current color keep tracking it (GL 2.1
 section 2.14.3): the call leaves them at the current color and sets the rest.
 `GL_COLOR_INDEXES` is stored for queries only (color-index lighting is not drawn).
 Errors: `GL_INVALID_ENUM` for another face or `pname`; `GL_INVALID_VALUE` for a shininess
 outside [0, 128], a value that is not finite or a null `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or points
 at as many values as `pname` has (4, 3 for `GL_COLOR_INDEXES`, 1 for `GL_SHININESS`).
 */
void ffvkMaterialfv(struct FfvkContext *ctx, uint32_t face, uint32_t pname, const float *params);

/*
 glMaterialiv: `ffvkMaterialfv` with integers (colors as GL 2.1 table 2.9 maps them).

 # Safety

 As `ffvkMaterialfv`.
 */
void ffvkMaterialiv(struct FfvkContext *ctx, uint32_t face, uint32_t pname, const int32_t *params);

/*
 glMaterialf: `GL_SHININESS` only; any other `pname` sets `GL_INVALID_ENUM`.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkMaterialf(struct FfvkContext *ctx, uint32_t face, uint32_t pname, float param);

/*
 glMateriali: `ffvkMaterialf` with an integer.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkMateriali(struct FfvkContext *ctx, uint32_t face, uint32_t pname, int32_t param);

/*
 glLightModelfv: `GL_LIGHT_MODEL_AMBIENT` (4 values), `GL_LIGHT_MODEL_LOCAL_VIEWER` and
 `GL_LIGHT_MODEL_TWO_SIDE` (non-zero is true), `GL_LIGHT_MODEL_COLOR_CONTROL`
 (`GL_SINGLE_COLOR` or `GL_SEPARATE_SPECULAR_COLOR`). Errors: `GL_INVALID_ENUM` for another
 `pname` or color control; `GL_INVALID_VALUE` for a value that is not finite or a null
 `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or points
 at as many values as `pname` has.
 */
void ffvkLightModelfv(struct FfvkContext *ctx, uint32_t pname, const float *params);

/*
 glLightModeliv: `ffvkLightModelfv` with integers.

 # Safety

 As `ffvkLightModelfv`.
 */
void ffvkLightModeliv(struct FfvkContext *ctx, uint32_t pname, const int32_t *params);

/*
 glLightModelf: the single-valued parameters (not `GL_LIGHT_MODEL_AMBIENT`, which sets
 `GL_INVALID_ENUM` here).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkLightModelf(struct FfvkContext *ctx, uint32_t pname, float param);

/*
 glLightModeli: `ffvkLightModelf` with an integer.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkLightModeli(struct FfvkContext *ctx, uint32_t pname, int32_t param);

/*
 glTexEnvfv on `GL_TEXTURE_ENV`, for the active unit (`ffvkActiveTexture`):
 `GL_TEXTURE_ENV_MODE` (`GL_MODULATE`, `GL_REPLACE`, `GL_DECAL`, `GL_BLEND`, `GL_ADD`,
 `GL_COMBINE`), `GL_TEXTURE_ENV_COLOR` (4 values, clamped to [0, 1]), or one of
 `GL_COMBINE`'s (GL 2.1 §3.8.13, table 3.24): `GL_COMBINE_RGB` and `GL_COMBINE_ALPHA`
 (`GL_REPLACE`, `GL_MODULATE`, `GL_ADD`, `GL_ADD_SIGNED`, `GL_INTERPOLATE`, `GL_SUBTRACT`,
 and for RGB `GL_DOT3_RGB`, `GL_DOT3_RGBA`), `GL_SRC0_RGB` .. `GL_SRC2_RGB` and
 `GL_SRC0_ALPHA` .. `GL_SRC2_ALPHA` (`GL_TEXTURE`, `GL_CONSTANT`, `GL_PRIMARY_COLOR`,
 `GL_PREVIOUS`, and `GL_TEXTURE0` .. `GL_TEXTURE3`: unit n's texel, sampled with unit n's
 texture and coordinates, ARB_texture_env_crossbar; a unit that is not enabled with a
 texture passes the previous color on), `GL_OPERAND0_RGB` .. `GL_OPERAND2_RGB`
 (`GL_SRC_COLOR`, `GL_ONE_MINUS_SRC_COLOR`, `GL_SRC_ALPHA`, `GL_ONE_MINUS_SRC_ALPHA`),
 `GL_OPERAND0_ALPHA` .. `GL_OPERAND2_ALPHA` (`GL_SRC_ALPHA`, `GL_ONE_MINUS_SRC_ALPHA`),
 `GL_RGB_SCALE` and `GL_ALPHA_SCALE` (1, 2 or 4); on `GL_POINT_SPRITE`: `GL_COORD_REPLACE`
 (zero is `GL_FALSE`, anything else `GL_TRUE`). Errors: `GL_INVALID_ENUM` for another
 target, `pname` or value (a dot product for `GL_COMBINE_ALPHA`, a color operand for an alpha
 argument, a `GL_TEXTUREn` source past the four units: `GL_TEXTURE4` and on, as Mesa refuses
 one past its own); `GL_INVALID_VALUE` for a scale other than 1, 2 or 4, a value that is not
 finite or a null `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or points
 at as many values as `pname` has.
 */
void ffvkTexEnvfv(struct FfvkContext *ctx, uint32_t target, uint32_t pname, const float *params);

/*
 glTexEnviv: `ffvkTexEnvfv` with integers.

 # Safety

 As `ffvkTexEnvfv`.
 */
void ffvkTexEnviv(struct FfvkContext *ctx, uint32_t target, uint32_t pname, const int32_t *params);

/*
 glTexEnvf: a single-valued name, `GL_TEXTURE_ENV_MODE` or one of `GL_COMBINE`'s, as
 `ffvkTexEnvfv` takes it (an enum given as a float is truncated); `GL_TEXTURE_ENV_COLOR`
 sets `GL_INVALID_ENUM`.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkTexEnvf(struct FfvkContext *ctx, uint32_t target, uint32_t pname, float param);

/*
 glTexEnvi: `ffvkTexEnvf` with an integer.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkTexEnvi(struct FfvkContext *ctx, uint32_t target, uint32_t pname, int32_t param);

/*
 glColorMaterial: which face(s) and parameter(s) track the current color while
 `GL_COLOR_MATERIAL` is enabled (and, enabled, writes the current color into them now).
 Errors: `GL_INVALID_ENUM` for another face or mode.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkColorMaterial(struct FfvkContext *ctx, uint32_t face_enum, uint32_t mode);

/*
 glNormal3f: the current normal, every vertex's normal in a draw whose layout has no normal
 array. Not normalized (GL normalizes only under `GL_NORMALIZE`); `GL_INVALID_VALUE` for a
 component that is not finite (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkNormal3f(struct FfvkContext *ctx, float x, float y, float z);

/*
 glNormal3b: `ffvkNormal3f` with each byte c converted as GL 2.1 converts signed bytes,
 (2c + 1)/255.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkNormal3b(struct FfvkContext *ctx, int8_t x, int8_t y, int8_t z);

/*
 glTexCoord4f: unit 0's current texture coordinates (`ffvkMultiTexCoord4f(GL_TEXTURE0, …)`,
 whatever the active unit), every vertex's in a textured draw whose layout has no texture
 coordinate array; `GL_INVALID_VALUE` for a component that is not finite (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkTexCoord4f(struct FfvkContext *ctx, float s, float t, float r, float q);

/*
 glTexCoord2f: `ffvkTexCoord4f` with r = 0 and q = 1.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkTexCoord2f(struct FfvkContext *ctx, float s, float t);

/*
 glAlphaFunc: the alpha test's function (`GL_NEVER` .. `GL_ALWAYS`; another value sets
 `GL_INVALID_ENUM`) and reference, clamped to [0, 1] as GL clamps it (a NaN reference sets
 `GL_INVALID_VALUE`: ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkAlphaFunc(struct FfvkContext *ctx, uint32_t func, float reference);

/*
 glSecondaryColor3f: the current secondary color (r, g, b, 1), every vertex's in a draw
 whose layout has no secondary color array, summed with lighting off under `GL_COLOR_SUM`;
 `GL_INVALID_VALUE` for a component that is not finite (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkSecondaryColor3f(struct FfvkContext *ctx, float r, float g, float b);

/*
 glColor4f: the current color, the color of every vertex of a draw without a color array,
 and (with `GL_COLOR_MATERIAL`) of the tracked material parameters. Unclamped, as in GL;
 `GL_INVALID_VALUE` for a component that is not finite (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkColor4f(struct FfvkContext *ctx, float r, float g, float b, float a);

/*
 glColor3f: `ffvkColor4f` with alpha 1.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkColor3f(struct FfvkContext *ctx, float r, float g, float b);

/*
 glColor4ub: each component c becomes c / 255.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkColor4ub(struct FfvkContext *ctx, uint8_t r, uint8_t g, uint8_t b, uint8_t a);

/*
 glColor3ub: `ffvkColor4ub` with alpha 255.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkColor3ub(struct FfvkContext *ctx, uint8_t r, uint8_t g, uint8_t b);

/*
 glShadeModel: `GL_FLAT` draws in ffvk's flat mode (each primitive its provoking vertex's
 color), `GL_SMOOTH` per vertex, or per fragment after `ffvkPerFragmentLighting`. Errors:
 `GL_INVALID_ENUM` for another mode.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkShadeModel(struct FfvkContext *ctx, uint32_t mode);

/*
 ffvk's extension: with `GL_SMOOTH`, evaluate the equation per fragment (Phong's
 interpolation) instead of per vertex. `GL_FLAT` still draws flat. Off initially.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkPerFragmentLighting(struct FfvkContext *ctx, uint8_t enabled);

/*
 The current modelview matrix (16 floats, column-major, as glLoadMatrixf): the layer sets
 it whenever its modelview changes. Light positions and spot directions given later are
 transformed by it, and draws use it. `GL_INVALID_VALUE` (matrix kept) for a null pointer
 or a component that is not finite.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `m` is null or points at 16
 floats.
 */
void ffvkLoadModelview(struct FfvkContext *ctx, const float *m);

/*
 The current projection matrix (16 floats, column-major, GL's clip space with z in
 [-w, w]): draws use it. Errors as `ffvkLoadModelview`.

 # Safety

 As `ffvkLoadModelview`.
 */
void ffvkLoadProjection(struct FfvkContext *ctx, const float *m);

/*
 The active unit's current texture matrix (its `GL_TEXTURE` stack's top; `ffvkActiveTexture`
 selects the unit). Errors as `ffvkLoadModelview`.

 # Safety

 As `ffvkLoadModelview`.
 */
void ffvkLoadTextureMatrix(struct FfvkContext *ctx, const float *m);

/*
 glFogf: `GL_FOG_MODE` (`GL_LINEAR`, `GL_EXP`, `GL_EXP2`), `GL_FOG_DENSITY` (≥ 0),
 `GL_FOG_START`, `GL_FOG_END`, `GL_FOG_COORD_SRC` (`GL_FOG_COORD`, `GL_FRAGMENT_DEPTH`) or
 `GL_FOG_INDEX` (color-index fog: kept for queries, drawing nothing in RGBA). A mode given as
 a float that is not finite is `GL_INVALID_VALUE` (ffvk's rule for every non-finite value,
 where GL would say `GL_INVALID_ENUM`). Errors: `GL_INVALID_ENUM` for another `pname` (`GL_FOG_COLOR` included: it has four values)
 or mode; `GL_INVALID_VALUE` for a negative density or a value that is not finite.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkFogf(struct FfvkContext *ctx,
              uint32_t pname,
              float param);

/*
 glFogi: `ffvkFogf` with an integer.

 # Safety

 As `ffvkFogf`.
 */
void ffvkFogi(struct FfvkContext *ctx, uint32_t pname, int32_t param);

/*
 glFogfv: `ffvkFogf`'s names, and `GL_FOG_COLOR` (4 values, clamped to [0, 1]).
 `GL_INVALID_VALUE` also for a null `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or points
 at as many values as `pname` has.
 */
void ffvkFogfv(struct FfvkContext *ctx, uint32_t pname, const float *params);

/*
 glFogiv: `ffvkFogfv` with integers (the color's map [-2^31, 2^31 - 1] onto [-1, 1], as GL
 maps integer colors).

 # Safety

 As `ffvkFogfv`.
 */
void ffvkFogiv(struct FfvkContext *ctx, uint32_t pname, const int32_t *params);

/*
 glFogCoordf: the current fog coordinate, every vertex's in draws whose layout has no fog
 coordinate array (read with `GL_FOG_COORD_SRC` `GL_FOG_COORD`); `GL_INVALID_VALUE` for a
 value that is not finite (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkFogCoordf(struct FfvkContext *ctx, float coord);

/*
 glHint: `GL_FOG_HINT` `GL_FASTEST` fogs per vertex, `GL_DONT_CARE` and `GL_NICEST` per
 fragment; GL's other hint targets are accepted and change nothing ffvk draws. Errors:
 `GL_INVALID_ENUM` for a target or mode GL does not name.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkHint(struct FfvkContext *ctx, uint32_t target, uint32_t mode);

/*
 glStencilFunc: both faces' stencil test: `func` (`GL_NEVER` .. `GL_ALWAYS`), the reference
 `ref` (kept as given; clamped to [0, 255], ffvk's 8 stencil bits, when tested and queried)
 and the mask both are ANDed with. Errors: `GL_INVALID_ENUM` for another func.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkStencilFunc(struct FfvkContext *ctx, uint32_t func, int32_t reference, uint32_t mask);

/*
 glStencilFuncSeparate: `ffvkStencilFunc` for `face` (`GL_FRONT`, `GL_BACK` or
 `GL_FRONT_AND_BACK`). Errors: `GL_INVALID_ENUM` for another face or func.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkStencilFuncSeparate(struct FfvkContext *ctx,
                             uint32_t face_enum,
                             uint32_t func,
                             int32_t reference,
                             uint32_t mask);

/*
 glStencilOp: both faces' actions when the stencil test fails (`sfail`), when it passes and
 the depth test fails (`dpfail`) and when both pass (`dppass`): `GL_KEEP`, `GL_ZERO`,
 `GL_REPLACE`, `GL_INCR`, `GL_DECR`, `GL_INVERT`, `GL_INCR_WRAP` or `GL_DECR_WRAP`. Errors:
 `GL_INVALID_ENUM` for another action.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkStencilOp(struct FfvkContext *ctx, uint32_t sfail, uint32_t dpfail, uint32_t dppass);

/*
 glStencilOpSeparate: `ffvkStencilOp` for `face`. Errors: `GL_INVALID_ENUM` for another face
 or action.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkStencilOpSeparate(struct FfvkContext *ctx,
                           uint32_t face_enum,
                           uint32_t sfail,
                           uint32_t dpfail,
                           uint32_t dppass);

/*
 glStencilMask: the stencil bits both faces' fragments may write. Never an error.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkStencilMask(struct FfvkContext *ctx, uint32_t mask);

/*
 glStencilMaskSeparate: `ffvkStencilMask` for `face`. Errors: `GL_INVALID_ENUM` for another
 face.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkStencilMaskSeparate(struct FfvkContext *ctx, uint32_t face_enum, uint32_t mask);

/*
 glClearStencil: the value a stencil clear writes, kept as given for
 `GL_STENCIL_CLEAR_VALUE` (the caller clears its own attachments). Never an error.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkClearStencil(struct FfvkContext *ctx, int32_t s);

/*
 glColorMask: which channels fragments write (non-zero is `GL_TRUE`). Never an error.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkColorMask(struct FfvkContext *ctx,
                   uint8_t red,
                   uint8_t green,
                   uint8_t blue,
                   uint8_t alpha);

/*
 glDepthMask: whether fragments write depth while the depth test is on (non-zero is
 `GL_TRUE`). Never an error.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkDepthMask(struct FfvkContext *ctx, uint8_t flag);

/*
 glDepthFunc: the depth test's function, `GL_NEVER` .. `GL_ALWAYS` (`GL_LESS` by default).
 Errors: `GL_INVALID_ENUM` for another func.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkDepthFunc(struct FfvkContext *ctx, uint32_t func);

/*
 glDepthRange: near and far, each clamped to [0, 1] as GL clamps them, kept for
 `GL_DEPTH_RANGE` queries (a draw's depth range is its viewport's: pass them to
 `ffvkViewport`). Errors: `GL_INVALID_VALUE` for a NaN (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkDepthRange(struct FfvkContext *ctx, double near, double far);

/*
 glBlendFunc: the source and destination factors of color and alpha while `GL_BLEND` is
 enabled (GL 2.1 table 4.2: `GL_ZERO`, `GL_ONE`, the `SRC`, `DST` and `CONSTANT` color and
 alpha factors and their `ONE_MINUS` forms, and, as a source only, `GL_SRC_ALPHA_SATURATE`).
 Errors: `GL_INVALID_ENUM` for another factor.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkBlendFunc(struct FfvkContext *ctx, uint32_t sfactor, uint32_t dfactor);

/*
 glBlendFuncSeparate: `ffvkBlendFunc` with color's and alpha's factors apart. Errors:
 `GL_INVALID_ENUM` for another factor.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkBlendFuncSeparate(struct FfvkContext *ctx,
                           uint32_t src_rgb,
                           uint32_t dst_rgb,
                           uint32_t src_alpha,
                           uint32_t dst_alpha);

/*
 glBlendEquation: color's and alpha's equation, `GL_FUNC_ADD` (the default),
 `GL_FUNC_SUBTRACT`, `GL_FUNC_REVERSE_SUBTRACT`, `GL_MIN` or `GL_MAX`. Errors:
 `GL_INVALID_ENUM` for another mode.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkBlendEquation(struct FfvkContext *ctx, uint32_t mode);

/*
 glBlendEquationSeparate: `ffvkBlendEquation` with color's and alpha's apart. Errors:
 `GL_INVALID_ENUM` for another mode.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkBlendEquationSeparate(struct FfvkContext *ctx, uint32_t mode_rgb, uint32_t mode_alpha);

/*
 glBlendColor: the constant the `GL_CONSTANT_*` factors read, each component clamped to
 [0, 1] as GL 2.1 clamps it. Errors: `GL_INVALID_VALUE` for a component that is not finite
 (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkBlendColor(struct FfvkContext *ctx, float red, float green, float blue, float alpha);

/*
 glLogicOp: the op used while `GL_COLOR_LOGIC_OP` is enabled, `GL_CLEAR` .. `GL_SET`
 (`GL_COPY` by default). Errors: `GL_INVALID_ENUM` for another op.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkLogicOp(struct FfvkContext *ctx, uint32_t opcode);

/*
 glPointParameterf: `GL_POINT_SIZE_MIN`, `GL_POINT_SIZE_MAX`, `GL_POINT_FADE_THRESHOLD_SIZE`
 (each ≥ 0) or `GL_POINT_SPRITE_COORD_ORIGIN` (`GL_UPPER_LEFT`, `GL_LOWER_LEFT`). A draw of
 points takes its size from `FfvkRaster::point_size`, times √(1 / (a + b d + c d²)) at the
 eye distance d where the attenuation is not (1, 0, 0), clamped to [min, max], and rounded
 to whole pixels unless `GL_POINT_SPRITE` is enabled. Errors: `GL_INVALID_ENUM` for another
 `pname` (`GL_POINT_DISTANCE_ATTENUATION` included: it has three values) or origin;
 `GL_INVALID_VALUE` for a negative size or threshold or a value that is not finite.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkPointParameterf(struct FfvkContext *ctx, uint32_t pname, float param);

/*
 glPointParameteri: `ffvkPointParameterf` with an integer.

 # Safety

 As `ffvkPointParameterf`.
 */
void ffvkPointParameteri(struct FfvkContext *ctx, uint32_t pname, int32_t param);

/*
 glPointParameterfv: `ffvkPointParameterf`'s names, and `GL_POINT_DISTANCE_ATTENUATION`
 (a, b, c). `GL_INVALID_VALUE` also for a null `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or points
 at as many values as `pname` has.
 */
void ffvkPointParameterfv(struct FfvkContext *ctx, uint32_t pname, const float *params);

/*
 glPointParameteriv: `ffvkPointParameterfv` with integers.

 # Safety

 As `ffvkPointParameterfv`.
 */
void ffvkPointParameteriv(struct FfvkContext *ctx, uint32_t pname, const int32_t *params);

/*
 glPolygonMode: how `face`'s polygons (`GL_FRONT`, `GL_BACK`, `GL_FRONT_AND_BACK`) are
 rasterized: `GL_POINT`, `GL_LINE` or `GL_FILL`. Errors: `GL_INVALID_ENUM` for another face or
 mode.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkPolygonMode(struct FfvkContext *ctx, uint32_t face_enum, uint32_t mode);

/*
 glPolygonOffset: the slope factor and constant of the offset enabled by
 `GL_POLYGON_OFFSET_FILL`, `_LINE` and `_POINT`. Errors: `GL_INVALID_VALUE` for a value that
 is not finite (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkPolygonOffset(struct FfvkContext *ctx, float factor, float units);

/*
 glLineStipple: the repeat factor (clamped to [1, 256] as GL clamps it) and the 16-bit
 pattern used while `GL_LINE_STIPPLE` is enabled. Never an error.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkLineStipple(struct FfvkContext *ctx, int32_t factor, uint16_t pattern);

/*
 glPointSize: the size of points, in pixels. Errors: `GL_INVALID_VALUE` for a size at or below
 0, or not finite (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkPointSize(struct FfvkContext *ctx, float size);

/*
 glLineWidth: the width of lines, in pixels. Errors: `GL_INVALID_VALUE` for a width at or
 below 0, or not finite (ffvk's choice).

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkLineWidth(struct FfvkContext *ctx, float width);

/*
 glCullFace: the faces culled while `GL_CULL_FACE` is enabled: `GL_FRONT`, `GL_BACK` (the
 default) or `GL_FRONT_AND_BACK`. Errors: `GL_INVALID_ENUM` for another mode.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkCullFace(struct FfvkContext *ctx, uint32_t mode);

/*
 glFrontFace: the winding of front-facing polygons, `GL_CW` or `GL_CCW` (the default).
 Errors: `GL_INVALID_ENUM` for another mode.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkFrontFace(struct FfvkContext *ctx, uint32_t mode);

/*
 glPolygonStipple: the 32 × 32 pattern `GL_POLYGON_STIPPLE` applies to filled polygons, 128
 bytes as GL unpacks them with the default pixel storage: rows of 4 bytes from the bottom row
 up, the most significant bit of each byte leftmost (`GL_UNPACK_LSB_FIRST` false). A draw with
 the stipple on needs the framebuffer's height (`ffvkFramebufferHeight`). Errors:
 `GL_INVALID_VALUE` for a null `mask`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `mask` is null or points at
 128 bytes.
 */
void ffvkPolygonStipple(struct FfvkContext *ctx, const uint8_t *mask);

/*
 The height in pixels of the framebuffer the context's draws render into (ffvk's call: a GL
 context knows its window's): GL counts `GL_POLYGON_STIPPLE`'s rows from the framebuffer's
 bottom, so a draw with the stipple on needs it (`FFVK_ERROR_STATE` at `ffvkDraw` otherwise).
 Call it when the framebuffer is made or resized. Errors: `GL_INVALID_VALUE` for 0.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkFramebufferHeight(struct FfvkContext *ctx, uint32_t height);

/*
 glEdgeFlag: the current edge flag (non-zero is `GL_TRUE`), kept for `GL_EDGE_FLAG` queries:
 a draw's flags are in its indices (`ffvkEdgeFlaggedIndices` takes each vertex's). Never an
 error.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkEdgeFlag(struct FfvkContext *ctx, uint8_t flag);

/*
 glTexGeni: `GL_TEXTURE_GEN_MODE` of the active unit's (`ffvkActiveTexture`) coordinate
 `coord` (`GL_S`, `GL_T`, `GL_R`, `GL_Q`):
 `GL_OBJECT_LINEAR`, `GL_EYE_LINEAR` (the initial mode), `GL_SPHERE_MAP` (S and T only),
 `GL_REFLECTION_MAP` or `GL_NORMAL_MAP` (S, T and R), used while the coordinate's
 `GL_TEXTURE_GEN_S` (`_T`, `_R`, `_Q`) is enabled (GL 2.1 §2.11.4). Errors:
 `GL_INVALID_ENUM` for another `coord`, another `pname` (`GL_OBJECT_PLANE` and
 `GL_EYE_PLANE` included: their four values take the vector forms), a value that is no mode,
 or a mode the coordinate does not take.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkTexGeni(struct FfvkContext *ctx, uint32_t coord, uint32_t pname, int32_t param);

/*
 glTexGenf: `ffvkTexGeni` with the mode's value as a float (truncated to an integer, as GL
 reads an enum given as a float; one that is not finite sets `GL_INVALID_VALUE`, ffvk's rule
 for every non-finite value).

 # Safety

 As `ffvkTexGeni`.
 */
void ffvkTexGenf(struct FfvkContext *ctx, uint32_t coord, uint32_t pname, float param);

/*
 glTexGend: `ffvkTexGenf` with a double.

 # Safety

 As `ffvkTexGeni`.
 */
void ffvkTexGend(struct FfvkContext *ctx, uint32_t coord, uint32_t pname, double param);

/*
 glTexGenfv: `ffvkTexGenf`'s `GL_TEXTURE_GEN_MODE`, and the coordinate's planes (p1, p2, p3,
 p4): `GL_OBJECT_PLANE`, kept as given, and `GL_EYE_PLANE`, stored in eye space as
 (p1 p2 p3 p4) M⁻¹ with M the context's modelview at this call (`ffvkLoadModelview`), as GL
 does; later modelview changes do not move it. Errors: as `ffvkTexGeni`, and
 `GL_INVALID_VALUE` for a null `params`, a plane value that is not finite, or (for the eye
 plane) a singular modelview (ffvk's choices: GL leaves those undefined).

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or points
 at as many values as `pname` has (4 for a plane, 1 for the mode).
 */
void ffvkTexGenfv(struct FfvkContext *ctx, uint32_t coord, uint32_t pname, const float *params);

/*
 glTexGeniv: `ffvkTexGenfv` with integers, a plane's converted directly to floats.

 # Safety

 As `ffvkTexGenfv`.
 */
void ffvkTexGeniv(struct FfvkContext *ctx, uint32_t coord, uint32_t pname, const int32_t *params);

/*
 glTexGendv: `ffvkTexGenfv` with doubles (a plane is stored as floats, the eye plane
 transformed in double precision first).

 # Safety

 As `ffvkTexGenfv`.
 */
void ffvkTexGendv(struct FfvkContext *ctx, uint32_t coord, uint32_t pname, const double *params);

/*
 glActiveTexture: `GL_TEXTURE0` .. `GL_TEXTURE3` becomes the active unit (`GL_ACTIVE_TEXTURE`,
 `GL_TEXTURE0` initially): the unit later `ffvkTexEnv*`, `ffvkTexGen*`,
 `ffvkLoadTextureMatrix`, `GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP`, `GL_TEXTURE_GEN_*` and
 `GL_COORD_REPLACE` act on,
 and whose state `ffvkGetTexEnv*`, `ffvkGetTexGen*`, `ffvkIsEnabled` and
 `GL_CURRENT_TEXTURE_COORDS` and `GL_TEXTURE_MATRIX` answer. Errors: `GL_INVALID_ENUM` for any
 other value (`GL_TEXTURE4` and past: ffvk has four units, and no shader image units beyond
 them), the active unit unchanged.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkActiveTexture(struct FfvkContext *ctx, uint32_t texture);

/*
 glMultiTexCoord4f: unit `target`'s (`GL_TEXTURE0` .. `GL_TEXTURE3`) current texture
 coordinates (s, t, r, q), whatever the active unit: every vertex's for that unit in a draw
 whose layout has no texture coordinate array for it (`ffvkTexCoord4f` is
 `ffvkMultiTexCoord4f(GL_TEXTURE0, …)`). Initially (0, 0, 0, 1) on every unit. Errors:
 `GL_INVALID_ENUM` for another target (GL 2.1 §2.7 leaves an invalid coordinate set
 undefined: ffvk refuses it); `GL_INVALID_VALUE` for a component that is not finite (ffvk's
 choice). Nothing changes on an error.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkMultiTexCoord4f(struct FfvkContext *ctx,
                         uint32_t target,
                         float s,
                         float t,
                         float r,
                         float q);

/*
 glMultiTexCoord2f: `ffvkMultiTexCoord4f` with r = 0 and q = 1.

 # Safety

 `ctx` is null or a live context used by one thread at a time.
 */
void ffvkMultiTexCoord2f(struct FfvkContext *ctx, uint32_t target, float s, float t);

/*
 glMultiTexCoord4fv: `ffvkMultiTexCoord4f` with (s, t, r, q) read from `v`. Errors as
 `ffvkMultiTexCoord4f`, and `GL_INVALID_VALUE` for a null or misaligned `v` (checked after
 the target).

 # Safety

 `ctx` is null or a live context used by one thread at a time; `v` is null or points at four
 floats.
 */
void ffvkMultiTexCoord4fv(struct FfvkContext *ctx, uint32_t target, const float *v);

/*
 Newell's teapot tessellated at `level` (1 ..= 64 steps per patch side), the mesh ffvk's
 examples and tests draw: y up (the lid), the spout toward +x and the handle toward −x,
 centred on the origin within x in [−1, 1], y in [−0.483, 0.483], z in [−0.613, 0.613]
 (Newell's patches closed by their bottom); counter-clockwise front faces, unit normals,
 colors in [0, 1]. Errors: `FFVK_ERROR_INVALID_ARGUMENT` for another level or a null
 `mesh`.

 # Safety

 `mesh` is null or writable.
 */
enum FfvkResult ffvkCreateTeapot(uint32_t level, struct FfvkMesh **mesh);

/*
 The mesh's arrays. Returns `FFVK_ERROR_INVALID_ARGUMENT` for a null pointer.

 # Safety

 `mesh` is null or live; `arrays` is null or writable.
 */
enum FfvkResult ffvkGetMeshArrays(const struct FfvkMesh *mesh, struct FfvkMeshArrays *arrays);

/*
 Frees a mesh; null is ignored.

 # Safety

 `mesh` is null or from `ffvkCreateTeapot`, not yet destroyed.
 */
void ffvkDestroyMesh(struct FfvkMesh *mesh);

/*
 GL's modes that Vulkan lacks, as indices of a mode it has, keeping GL's winding and
 provoking vertex: `GL_QUADS`, `GL_QUAD_STRIP` and `GL_POLYGON` become `GL_TRIANGLES`,
 `GL_LINE_LOOP` becomes `GL_LINES`; the other modes are copied unchanged. `vertices` are
 the `count` vertex numbers GL would read (the index array of glDrawElements; for
 glDrawArrays' `first + i`, `ffvkPrimitiveIndicesRange` needs no array). Writes at most
 `capacity` indices to `out` (null to ask the size) and the needed count to `*written`, and
 the mode to draw them with to `*draw_mode`. A size query (null `out`) reads nothing from
 `vertices`; nothing is allocated, whatever the count. Errors:
 `FFVK_ERROR_INVALID_ARGUMENT` for an unknown mode, a null `vertices` (with a count), a
 null `written` or `draw_mode`, a count whose indices would number more than a `uint32_t`
 holds (e.g. `GL_POLYGON` of more than 1431655767 vertices; nothing written then), or a
 `capacity` below the needed count (nothing written to `out` then).

 # Safety

 `vertices` points at `count` values (unless `out` is null); `out` is null or has room for
 `capacity`.
 */
enum FfvkResult ffvkPrimitiveIndices(uint32_t mode,
                                     const uint32_t *vertices,
                                     uint32_t count,
                                     uint32_t *out,
                                     uint32_t capacity,
                                     uint32_t *written,
                                     uint32_t *draw_mode);

/*
 `ffvkPrimitiveIndices` for `glDrawArrays(mode, first, count)`: the vertex numbers are
 `first`, `first + 1`, … `first + count - 1`, so no array is passed. The outputs, the size
 query and the errors are `ffvkPrimitiveIndices`'s, and: `FFVK_ERROR_INVALID_ARGUMENT` when
 `first + count` passes 2^32 (the last vertex number would not fit a `uint32_t`);
 `FFVK_ERROR_OUT_OF_MEMORY` when the host cannot hold the `count` vertex numbers ffvk makes
 while it writes `GL_QUADS`, `GL_QUAD_STRIP`, `GL_POLYGON` or `GL_LINE_LOOP` indices (4 bytes
 each, freed before it returns; the other modes and a size query allocate nothing).

 # Safety

 `out` is null or has room for `capacity`.
 */
enum FfvkResult ffvkPrimitiveIndicesRange(uint32_t mode,
                                          uint32_t first,
                                          uint32_t count,
                                          uint32_t *out,
                                          uint32_t capacity,
                                          uint32_t *written,
                                          uint32_t *draw_mode);

/*
 GL's polygons with their edge flags (GL 2.1 §2.6.2), for draws in polygon mode `GL_LINE` or
 `GL_POINT`: `GL_TRIANGLES`, `GL_QUADS`, `GL_QUAD_STRIP` or `GL_POLYGON` over the `count`
 vertex numbers `vertices` (as `ffvkPrimitiveIndices` takes them), as indices to draw with
 mode `GL_TRIANGLES_ADJACENCY` (`ffvkDraw`; the device's `geometryShader`,
 `FFVK_FEATURE_GEOMETRY_SHADER`): the same triangles as `ffvkPrimitiveIndices` makes, six
 indices each, whose adjacency indices mark the edges GL draws: a quad's four sides and not
 its diagonal, a polygon's sides and not its fan, and of those only the edges whose first
 vertex's edge flag is `GL_TRUE`. `edge_flags` is null (every flag `GL_TRUE`, GL's default
 edge flag) or GL's edge flag array (`glEdgeFlagPointer`): `flag_count` flags (non-zero:
 `GL_TRUE`), one per vertex number; a caller whose current edge flag (`glEdgeFlag`) is
 `GL_FALSE` passes flags of zero. `GL_QUAD_STRIP` takes no flags, as in GL (every side of
 every quad is drawn). Filled, such a draw looks as the `ffvkPrimitiveIndices` draw does.
 Writes at most `capacity` indices to `out` (null to ask the size) and the needed count to
 `*written`. Errors: `FFVK_ERROR_INVALID_ARGUMENT` for another mode, a null `vertices` (with
 a count) or `written`, a vertex number at or past `flag_count` (with flags; nothing written
 to `out` then), a count whose indices would number more than a `uint32_t` holds, or a
 `capacity` below the needed count (nothing written to `out` then).

 # Safety

 `vertices` points at `count` values and `edge_flags` at `flag_count` (neither is read when
 `out` is null, but `vertices` must not be null with a count); `out` is null or has room for
 `capacity`. A size query (null `out`) checks the mode, the count and the pointers only: the
 flags are checked when the indices are written.
 */
enum FfvkResult ffvkEdgeFlaggedIndices(uint32_t mode,
                                       const uint32_t *vertices,
                                       uint32_t count,
                                       const uint8_t *edge_flags,
                                       uint32_t flag_count,
                                       uint32_t *out,
                                       uint32_t capacity,
                                       uint32_t *written);

/*
 glGetLightfv: a light's parameter as stored: positions and spot directions in eye
 space. Errors: `GL_INVALID_ENUM` for a light past `GL_MAX_LIGHTS` or an unknown
 `pname`; `GL_INVALID_VALUE` for a null `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (16 for a matrix). Nothing is written when an error is
 set.
 */
void ffvkGetLightfv(struct FfvkContext *ctx, uint32_t light, uint32_t pname, float *params);

/*
 glGetLightiv: `ffvkGetLightfv` as integers (colors by GL's linear mapping, the rest
 rounded).

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (16 for a matrix). Nothing is written when an error is
 set.
 */
void ffvkGetLightiv(struct FfvkContext *ctx, uint32_t light, uint32_t pname, int32_t *params);

/*
 glGetMaterialfv for `GL_FRONT` or `GL_BACK` (`GL_FRONT_AND_BACK` sets
 `GL_INVALID_ENUM`, as in GL). Errors: `GL_INVALID_ENUM` for another face or `pname`
 (`GL_AMBIENT_AND_DIFFUSE` is not a query); `GL_INVALID_VALUE` for a null `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (16 for a matrix). Nothing is written when an error is
 set.
 */
void ffvkGetMaterialfv(struct FfvkContext *ctx, uint32_t face, uint32_t pname, float *params);

/*
 glGetMaterialiv: `ffvkGetMaterialfv` as integers.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (16 for a matrix). Nothing is written when an error is
 set.
 */
void ffvkGetMaterialiv(struct FfvkContext *ctx, uint32_t face, uint32_t pname, int32_t *params);

/*
 glGetTexEnvfv on `GL_TEXTURE_ENV`: the active unit's (`ffvkActiveTexture`)
 `GL_TEXTURE_ENV_MODE`, `GL_TEXTURE_ENV_COLOR` or one of `GL_COMBINE`'s names
 (`ffvkTexEnvfv`): its enum (a `GL_TEXTUREn` source as `GL_TEXTURE0 + n`), or the scale (1, 2
 or 4); on `GL_POINT_SPRITE`, the active unit's `GL_COORD_REPLACE`. Errors:
 `GL_INVALID_ENUM` for another target or `pname`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (16 for a matrix). Nothing is written when an error is
 set.
 */
void ffvkGetTexEnvfv(struct FfvkContext *ctx, uint32_t target, uint32_t pname, float *params);

/*
 glGetTexEnviv: `ffvkGetTexEnvfv` as integers.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (16 for a matrix). Nothing is written when an error is
 set.
 */
void ffvkGetTexEnviv(struct FfvkContext *ctx, uint32_t target, uint32_t pname, int32_t *params);

/*
 glGetTexGenfv: the active unit's coordinate `coord`'s (`GL_S`, `GL_T`, `GL_R`, `GL_Q`) `GL_TEXTURE_GEN_MODE`
 (one value, the mode's enum), `GL_OBJECT_PLANE` or `GL_EYE_PLANE` (four values, as stored:
 the eye plane in eye space, as `ffvkTexGenfv` transformed it) (GL 2.1 §2.11.4, §6.1.3).
 Errors: `GL_INVALID_ENUM` for another `coord` or `pname`; `GL_INVALID_VALUE` for a null
 `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (4 for a plane). Nothing is written when an error is
 set.
 */
void ffvkGetTexGenfv(struct FfvkContext *ctx,
                     uint32_t coord,
                     uint32_t pname,
                     float *params);

/*
 glGetTexGeniv: `ffvkGetTexGenfv` as integers, a plane's values rounded to the nearest
 integer (GL 2.1 §6.1.2).

 # Safety

 As `ffvkGetTexGenfv`.
 */
void ffvkGetTexGeniv(struct FfvkContext *ctx, uint32_t coord, uint32_t pname, int32_t *params);

/*
 glGetTexGendv: `ffvkGetTexGenfv` as doubles.

 # Safety

 As `ffvkGetTexGenfv`.
 */
void ffvkGetTexGendv(struct FfvkContext *ctx, uint32_t coord, uint32_t pname, double *params);

/*
 glGetFloatv for the names of the state ffvk keeps: `GL_LIGHTING`, `GL_LIGHTi`,
 `GL_COLOR_MATERIAL`, `GL_COLOR_MATERIAL_FACE`, `GL_COLOR_MATERIAL_PARAMETER`,
 `GL_NORMALIZE`, `GL_RESCALE_NORMAL`, `GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP`,
 `GL_LIGHT_MODEL_AMBIENT`,
 `GL_LIGHT_MODEL_LOCAL_VIEWER`, `GL_LIGHT_MODEL_TWO_SIDE`, `GL_LIGHT_MODEL_COLOR_CONTROL`,
 `GL_SHADE_MODEL`, `GL_CURRENT_COLOR`, `GL_CURRENT_NORMAL`, `GL_CURRENT_TEXTURE_COORDS`,
 `GL_MAX_LIGHTS` (16) and the modelview, projection and texture matrices; the texture units:
 `GL_ACTIVE_TEXTURE` (`GL_TEXTURE0` .. `GL_TEXTURE3`, `ffvkActiveTexture`),
 `GL_MAX_TEXTURE_UNITS` and `GL_MAX_TEXTURE_COORDS` (4), and the active unit's
 `GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP`, `GL_TEXTURE_GEN_*`, `GL_CURRENT_TEXTURE_COORDS` and
 `GL_TEXTURE_MATRIX`;
 and the stages
 around lighting: `GL_COLOR_SUM`, `GL_CURRENT_SECONDARY_COLOR`, `GL_FOG`, `GL_FOG_MODE`,
 `GL_FOG_DENSITY`, `GL_FOG_START`, `GL_FOG_END`, `GL_FOG_COLOR`, `GL_FOG_INDEX`,
 `GL_FOG_COORD_SRC`, `GL_FOG_HINT`, `GL_CURRENT_FOG_COORD`, `GL_ALPHA_TEST`,
 `GL_ALPHA_TEST_FUNC`, `GL_ALPHA_TEST_REF`, `GL_CLIP_PLANEi` (enabled),
 `GL_MAX_CLIP_PLANES` (6), `GL_TEXTURE_GEN_S`, `_T`, `_R`, `_Q` (enabled); and the points': `GL_POINT_SIZE_MIN`, `GL_POINT_SIZE_MAX`,
 `GL_POINT_FADE_THRESHOLD_SIZE`, `GL_POINT_DISTANCE_ATTENUATION` (3 values),
 `GL_POINT_SPRITE` and `GL_POINT_SPRITE_COORD_ORIGIN`; and the raster state's:
 `GL_POLYGON_MODE` (front, back), `GL_POLYGON_OFFSET_FACTOR`, `GL_POLYGON_OFFSET_UNITS`,
 `GL_POLYGON_OFFSET_FILL`, `_LINE`, `_POINT`, `GL_EDGE_FLAG`, `GL_LINE_STIPPLE`, `GL_POLYGON_STIPPLE`,
 `GL_LINE_STIPPLE_PATTERN`, `GL_LINE_STIPPLE_REPEAT`, `GL_DEPTH_RANGE`, `GL_DEPTH_TEST`,
 `GL_DEPTH_WRITEMASK`, `GL_DEPTH_FUNC`, `GL_STENCIL_TEST`, `GL_STENCIL_FUNC`, `GL_STENCIL_REF`
 (clamped to [0, 255]), `GL_STENCIL_VALUE_MASK`, `GL_STENCIL_FAIL`,
 `GL_STENCIL_PASS_DEPTH_FAIL`, `GL_STENCIL_PASS_DEPTH_PASS`, `GL_STENCIL_WRITEMASK`, their
 `GL_STENCIL_BACK_*` forms, `GL_STENCIL_CLEAR_VALUE`, `GL_COLOR_WRITEMASK` (4 values),
 `GL_BLEND`, `GL_BLEND_SRC_RGB` (`GL_BLEND_SRC`), `GL_BLEND_DST_RGB` (`GL_BLEND_DST`),
 `GL_BLEND_SRC_ALPHA`, `GL_BLEND_DST_ALPHA`, `GL_BLEND_EQUATION_RGB`,
 `GL_BLEND_EQUATION_ALPHA`, `GL_BLEND_COLOR`, `GL_COLOR_LOGIC_OP`, `GL_LOGIC_OP_MODE`,
 `GL_CULL_FACE`, `GL_CULL_FACE_MODE`, `GL_FRONT_FACE`, `GL_POINT_SIZE` and `GL_LINE_WIDTH`.
 Errors: `GL_INVALID_ENUM` for any other name (a layer answers the rest of GL's state
 itself); `GL_INVALID_VALUE` for a null `params`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (16 for a matrix). Nothing is written when an error is
 set.
 */
void ffvkGetFloatv(struct FfvkContext *ctx,
                   uint32_t pname,
                   float *params);

/*
 glGetIntegerv: `ffvkGetFloatv`'s names as integers.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (16 for a matrix). Nothing is written when an error is
 set.
 */
void ffvkGetIntegerv(struct FfvkContext *ctx, uint32_t pname, int32_t *params);

/*
 glGetBooleanv: `ffvkGetFloatv`'s names as `GL_TRUE` (non-zero) or `GL_FALSE`.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `params` is null or has room
 for as many values as the name has (16 for a matrix). Nothing is written when an error is
 set.
 */
void ffvkGetBooleanv(struct FfvkContext *ctx, uint32_t pname, uint8_t *params);

/*
 glGetPolygonStipple: the polygon stipple's 128 bytes as `ffvkPolygonStipple` takes them
 (GL's default pixel storage); all ones until set. Errors: `GL_INVALID_VALUE` for a null
 `mask`. Nothing is written when an error is set.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `mask` is null or has room
 for 128 bytes.
 */
void ffvkGetPolygonStipple(struct FfvkContext *ctx, uint8_t *mask);

/*
 glGetClipPlane: the plane's equation as stored, in eye space (four doubles). Errors:
 `GL_INVALID_ENUM` for another `plane`; `GL_INVALID_VALUE` for a null `equation`. Nothing is
 written when an error is set.

 # Safety

 `ctx` is null or a live context used by one thread at a time; `equation` is null or has room
 for four doubles.
 */
void ffvkGetClipPlane(struct FfvkContext *ctx, uint32_t plane, double *equation);

/*
 Makes a renderer on the caller's device: checks every value of `info` before Vulkan is
 touched, then the device (Vulkan 1.3, dynamic rendering, the features `enabled_features`
 claims, the formats' features and sample counts, vertex limits), and makes the pipeline
 layout; pipelines are made on the first draw that needs each (about 15 ms on lavapipe).
 Returns `FFVK_SUCCESS` with `*renderer` set, or an error code with `*renderer` null:
 `FFVK_ERROR_INVALID_ARGUMENT` (a null pointer or handle, a `struct_size` that is not a
 published version's, 0 or more than `FFVK_MAX_FRAMES_IN_FLIGHT` frames, more than
 `FFVK_MAX_VERTEX_BINDINGS` bindings, unknown feature bits, a format, sample count or
 vertex layout that is invalid or that the device does not support; the message names the
 field, its value and what was expected),
 `FFVK_ERROR_MISSING_FEATURE`, `FFVK_ERROR_OUT_OF_MEMORY`, `FFVK_ERROR_VULKAN`. Records
 nothing.

 # Safety

 `renderer` is null or writable; `info` is null or points at the `struct_size` bytes of a
 create info as the caller's header declares it; the handles in `info` are live, `device`
 was created from `physical_device` of `instance` with the features `enabled_features` names,
 and all of them outlive the renderer.
 */
enum FfvkResult ffvkCreateRenderer(const struct FfvkRendererCreateInfo *info,
                                   struct FfvkRenderer **renderer);

/*
 Frees the renderer and everything it created; null is ignored. Records nothing. The
 caller first makes sure no submitted command buffer still uses it (waits on its fences).

 # Safety

 `renderer` is null or a renderer from `ffvkCreateRenderer` not yet destroyed, whose
 device is still alive.
 */
void ffvkDestroyRenderer(struct FfvkRenderer *renderer);

/*
 Starts a frame slot (0 .. frames_in_flight - 1): its memory will be rewritten by the draws
 recorded next. Call it once the fence of the submission that last used this slot has
 signalled. Records nothing.

 # Safety

 `renderer` is null or live and used by one thread at a time.
 */
enum FfvkResult ffvkBeginFrame(struct FfvkRenderer *renderer, uint32_t slot);

/*
 Opens a recording scope on `cmd` for frame slot `slot`, which `ffvkBeginFrame` has begun
 (several scopes may follow one `ffvkBeginFrame`; their draws share the slot's memory).
 `cmd` is in the recording state inside the caller's `vkCmdBeginRendering` on attachments of
 the create info's formats, with viewport and scissor set (both dynamic state). Between this
 call and `ffvkEndDraws` the caller records nothing of its own into `cmd`; between scopes it
 may (viewports, scissors, clears, barriers, rendering passes), and after binding anything of
 its own (a pipeline, descriptor sets, vertex or index buffers) or resetting `cmd` it calls
 `ffvkForgetBindings` before the next scope. Records nothing itself.

 # Safety

 `renderer` is null or live and used by one thread at a time; `cmd` is a command buffer of
 the renderer's device.
 */
enum FfvkResult ffvkBeginDraws(struct FfvkRenderer *renderer, VkCommandBuffer cmd, uint32_t slot);

/*
 Adds a draw to the open scope: the context's state now (lights, materials, switches, its
 modelview and projection) is captured, so the caller may change the context right after.
 The draw is checked and its state written into the slot's memory now (its pipeline is made
 now if it is new: about 15 ms on lavapipe); `ffvkEndDraws` records it. A refused draw is
 not added and the scope stays open with the draws before it. Errors:
 `FFVK_ERROR_INVALID_ARGUMENT` (no open scope, a null pointer, a `struct_size` that is not a
 published version's, a mode ffvk does not draw directly, a buffer count other than the
 layout's bindings, a raster enum that is not one ffvk passes to Vulkan (see `FfvkRaster`), a `raster_source`
 other than `FFVK_RASTER_SOURCE_DRAW` and `FFVK_RASTER_SOURCE_CONTEXT`,
 blending into a color
 format the device cannot blend, a point size or line width out of the device's range, a
 textured draw without texture coordinates, a cube map from `ffvkCreateCubeMap` in a
 `texture*` field or a 2D texture in a `cube_map*` one: the message names the field and unit),
 `FFVK_ERROR_STATE` (the context's state cannot be drawn: a soft spot cone wider than its
 cutoff, a modelview that cannot be inverted while lighting, a fill with `GL_POLYGON_STIPPLE`
 on and no `ffvkFramebufferHeight`), `FFVK_ERROR_MISSING_FEATURE` (`GL_FLAT`, a point size or
 a line width, a `GL_CLIP_PLANEi` enabled, a polygon mode, logic op or line stipple, or a
 `GL_TRIANGLES_ADJACENCY` draw, that the create info's `enabled_features` did not declare), `FFVK_ERROR_OUT_OF_MEMORY`, `FFVK_ERROR_VULKAN` (making the pipeline).

 # Safety

 `renderer` and `ctx` are null or live and used by this thread only; `draw` is null or
 points at the `struct_size` bytes of a draw info as the caller's header declares it; its
 buffers are the caller's live buffers of the renderer's device, and its textures are null
 or live during this call. `ffvkDraw` copies what each texture names, so a texture may be
 destroyed as soon as it returns (`ffvkEndDraws` records the copy); the view and sampler it
 names stay alive until the command buffer has executed.
 */
enum FfvkResult ffvkDraw(struct FfvkRenderer *renderer,
                         const struct FfvkContext *ctx,
                         const struct FfvkDrawInfo *draw);

/*
 Closes the scope: records every draw `ffvkDraw` added since `ffvkBeginDraws` into its
 command buffer as one run (binding only what changes between draws; consecutive draws of
 one geometry become instances). Records: bind pipeline, bind ffvk's descriptor sets at
 their dynamic offsets, bind the caller's vertex and index buffers and ffvk's record
 buffer, draw, each bind only where it differs from what ffvk last bound in the same command
 buffer (since `ffvkBeginFrame` or `ffvkForgetBindings`): a scope per draw, as a GL layer
 records `glDrawElements` by `glDrawElements`, rebinds nothing that did not change. They
 stay bound afterwards. A scope without draws records nothing. Errors:
 `FFVK_ERROR_INVALID_ARGUMENT` when no scope is open; the draws were checked when added.

 # Safety

 `renderer` is null or live and used by one thread at a time; the scope's command buffer is
 recording as `ffvkBeginDraws` requires; the draws' buffers, and the image views and samplers
 their textures name, are live and stay so until the command buffer has executed (the
 `FfvkTexture` objects themselves are not read again: `ffvkDraw` copied them).
 */
enum FfvkResult ffvkEndDraws(struct FfvkRenderer *renderer);

/*
 Forgets what ffvk bound: the next scope binds everything its draws need. Call it after
 recording commands of your own that bind a pipeline, descriptor sets, vertex buffers or an
 index buffer into a command buffer ffvk draws into, or after resetting such a command
 buffer (`ffvkBeginFrame` forgets too). Records nothing. Errors:
 `FFVK_ERROR_INVALID_ARGUMENT` for a null renderer or while a scope is open.

 # Safety

 `renderer` is null or live and used by one thread at a time.
 */
enum FfvkResult ffvkForgetBindings(struct FfvkRenderer *renderer);

/*
 Adds a vertex layout to `renderer` and writes its handle to `*layout`: draws name it in
 `FfvkDrawInfo::layout` (null there: the create info's layout) and pass one buffer per
 binding of it. Checked as the create info's layout is (formats each array takes, offsets
 within strides, the device's limits and vertex formats); pipelines for it are made on the
 first draw that needs them. An equal layout made before shares its pipelines. Free the
 handle with `ffvkDestroyVertexLayout` (the renderer keeps the layout's pipelines until it is
 destroyed). Errors: `FFVK_ERROR_INVALID_ARGUMENT` naming the field, value and what was
 expected (nothing written to `*layout` then), or a Vulkan error.

 # Safety

 `renderer` is null or live and used by one thread at a time; `info` is null or points at
 `info->struct_size` bytes of an `FfvkVertexLayoutInfo` whose pointers are null or point at
 what their counts say; `layout` is null or points at room for one pointer.
 */
enum FfvkResult ffvkCreateVertexLayout(struct FfvkRenderer *renderer,
                                       const struct FfvkVertexLayoutInfo *info,
                                       struct FfvkVertexLayout **layout);

/*
 Frees a layout handle from `ffvkCreateVertexLayout`; null does nothing. Draws recorded with
 it stay valid (the renderer keeps the layout's pipelines).

 # Safety

 `layout` is null or from `ffvkCreateVertexLayout`, not yet destroyed, and named by no draw
 of an open scope.
 */
void ffvkDestroyVertexLayout(struct FfvkVertexLayout *layout);

/*
 Fills `raster` with GL's initial raster state: no culling, `GL_CCW` front faces, depth
 test off with writes on and `GL_LESS`, blending off (factors ONE, ZERO, ADD), point size
 and line width 1.

 # Safety

 `raster` is null (ignored) or writable.
 */
void ffvkRasterDefaults(struct FfvkRaster *raster);

/*
 Makes a texture binding naming the caller's image view (2D, color, sampled as floats, in
 `VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL` whenever a draw that uses it executes) and
 sampler. ffvk owns the descriptor set; the view and sampler stay the caller's. Records
 nothing. Its base internal format is `GL_RGBA` (`ffvkCreateTextureWithFormat` gives
 another). Returns `FFVK_SUCCESS` with `*texture` set, or an error code with `*texture` null
 (`FFVK_ERROR_INVALID_ARGUMENT` for a null pointer or handle).

 # Safety

 `renderer` is null or live; `view` and `sampler` are live objects of its device and outlive
 every command buffer that draws with the texture; `texture` is null or writable.
 */
enum FfvkResult ffvkCreateTexture(struct FfvkRenderer *renderer,
                                  VkImageView view,
                                  VkSampler sampler,
                                  struct FfvkTexture **texture);

/*
 `ffvkCreateTexture` with the texture's base internal format (`glTexImage2D`'s
 `internalformat`, GL 2.1 table 3.15): `GL_ALPHA`, `GL_LUMINANCE`, `GL_LUMINANCE_ALPHA`,
 `GL_INTENSITY`, `GL_RGB` or `GL_RGBA`. It says which components the texture has, and so
 what the texture environment reads (table 3.22): a `GL_LUMINANCE` light map modulates the
 color and leaves the alpha, a `GL_ALPHA` texture leaves the color, `GL_INTENSITY` is its
 value in all four. The view gives the components as GL converts RGBA pixels: luminance and
 intensity are the view's R, alpha its A. A `GL_LUMINANCE` or `GL_INTENSITY` image of
 `VK_FORMAT_R8_UNORM` needs no swizzle; a `GL_ALPHA` one of `R8_UNORM` needs the view's
 `components.a = VK_COMPONENT_SWIZZLE_R`, a `GL_LUMINANCE_ALPHA` one of `R8G8_UNORM`
 `components.a = VK_COMPONENT_SWIZZLE_G`. A component the format lacks is never read. The
 bits and any sRGB decode are the view's `VkFormat`'s, so a sized format (`GL_LUMINANCE8`,
 `GL_SRGB8_ALPHA8`) is refused naming the base format to give.

 The format is fixed for the binding's life: `ffvkDraw` keys the draw's pipeline on it and
 `ffvkEndDraws` reads it again to record, so a binding whose format could change in between
 would record a draw other than the one checked. A program that redefines a texture with
 another `internalformat` makes another binding of its view (a binding is no Vulkan object
 and cheap to make; several of one view may live at once) and destroys the old one with
 `ffvkDestroyTexture` once no submitted command buffer uses it.

 Returns `FFVK_SUCCESS` with `*texture` set, or an error code with `*texture` null:
 `FFVK_ERROR_INVALID_ARGUMENT` for a null pointer or handle, or an `internalformat` that is
 none of the six (the message names the function, the parameter, the value by its GL name
 and what was expected), as the renderer's entry points refuse any enum they do not take.

 # Safety

 As `ffvkCreateTexture`.
 */
enum FfvkResult ffvkCreateTextureWithFormat(struct FfvkRenderer *renderer,
                                            VkImageView view,
                                            VkSampler sampler,
                                            uint32_t internalformat,
                                            struct FfvkTexture **texture);

/*
 Makes a cube map binding (`GL_TEXTURE_CUBE_MAP`'s texture object) naming the caller's image
 view and sampler, for `FfvkDrawInfo`'s `cube_map` .. `cube_map3` (version 5). The view is a
 `VK_IMAGE_VIEW_TYPE_CUBE` view of six array layers in GL's face order
 (`GL_TEXTURE_CUBE_MAP_POSITIVE_X`, `_NEGATIVE_X`, `_POSITIVE_Y`, `_NEGATIVE_Y`,
 `_POSITIVE_Z`, `_NEGATIVE_Z`), each face's row 0 at t = 0 as glTexImage2D's first row,
 color, sampled as floats, in `VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL` whenever a draw that
 uses it executes. GL 2.1 filters each face on its own: a sampler created with
 `VK_SAMPLER_CREATE_NON_SEAMLESS_CUBE_MAP_BIT_EXT` in its flags does so (the device needs
 `VK_EXT_non_seamless_cube_map` enabled: `FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP` from
 `ffvkDeviceRequirements`); without it, linear filtering near an edge also reads the
 neighbouring face (Vulkan's seamless filtering). ffvk owns the descriptor set; the view
 and sampler stay the caller's. Records nothing. Its base internal format is `GL_RGBA`
 (`ffvkCreateCubeMapWithFormat` gives another). Free it with `ffvkDestroyTexture`. Returns
 `FFVK_SUCCESS` with `*cube_map` set, or an error code with `*cube_map` null
 (`FFVK_ERROR_INVALID_ARGUMENT` for a null or misaligned pointer or a null handle).

 A cube map is drawn only from a `cube_map*` field and a 2D texture only from a `texture*`
 one: `ffvkDraw` refuses either in the other's field, naming the field and the unit.

 # Safety

 As `ffvkCreateTexture`: `renderer` is null or live; `view` and `sampler` are live objects of
 its device and outlive every command buffer that draws with the cube map; `cube_map` is null
 or writable.
 */
enum FfvkResult ffvkCreateCubeMap(struct FfvkRenderer *renderer,
                                  VkImageView view,
                                  VkSampler sampler,
                                  struct FfvkTexture **cube_map);

/*
 `ffvkCreateCubeMap` with the cube map's base internal format, every face's: as
 `ffvkCreateTextureWithFormat` takes it, read from the view as it reads it, and fixed for the
 binding's life likewise. Errors as `ffvkCreateTextureWithFormat`'s.

 # Safety

 As `ffvkCreateCubeMap`.
 */
enum FfvkResult ffvkCreateCubeMapWithFormat(struct FfvkRenderer *renderer,
                                            VkImageView view,
                                            VkSampler sampler,
                                            uint32_t internalformat,
                                            struct FfvkTexture **cube_map);

/*
 Frees a texture or cube map binding; null is ignored. It may be freed as soon as the last
 `ffvkDraw` that names it has returned, inside an open scope too: `ffvkDraw` copies what it
 names, and the binding is no Vulkan object. The view and sampler it names stay the
 caller's, alive until every command buffer that draws with them has executed.

 # Safety

 `texture` is null or from `ffvkCreateTexture` or `ffvkCreateCubeMap`, not yet destroyed.
 */
void ffvkDestroyTexture(struct FfvkTexture *texture);

/*
 The message of the last call on this thread that returned an error code (or set a GL error
 through a context): what failed, the value, what was expected. Never null; "" before any
 failure. `ffvkDeviceRequirements` sets it when it succeeds too: what the device lacks, or
 "". The string is ffvk's, valid until the next ffvk call on this thread.
 */
const char *ffvkResultMessage(void);

/*
 Tells the caller what to enable on the device it is about to create for ffvk, and fills it
 in: call it after choosing `physical_device` and before `vkCreateDevice`, with the
 `VkPhysicalDeviceFeatures2` (sType `VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2`) whose
 chain the caller then passes as `VkDeviceCreateInfo::pNext` (with `pEnabledFeatures` null),
 and its own features already set in it. ffvk only sets features to `VK_TRUE`, never clears
 one:

 - `dynamicRendering` (required) in the chain's `VkPhysicalDeviceVulkan13Features` (or
   `VkPhysicalDeviceDynamicRenderingFeatures`): the chain must hold one of them;
 - `provokingVertexLast` in a `VkPhysicalDeviceProvokingVertexFeaturesEXT` of the chain, when
   the device supports it (`GL_FLAT` needs it), with `VK_EXT_provoking_vertex` listed. Chain
   one whatever the device: where the device lacks the extension or the feature, ffvk takes
   the struct out of the chain (Vulkan forbids the struct of an extension not enabled);
 - `wideLines` and `largePoints` in `features->features`, where supported (line widths and
   point sizes other than 1);
 - `shaderClipDistance` in `features->features`, where supported (draws with a user clip
   plane enabled);
 - `fillModeNonSolid`, `logicOp`, and `geometryShader` with
   `shaderTessellationAndGeometryPointSize`, in `features->features`, where supported (polygon
   modes `GL_LINE` and `GL_POINT`; `GL_COLOR_LOGIC_OP`; GL's edge flags, draws of
   `GL_TRIANGLES_ADJACENCY`);
 - `bresenhamLines` and `stippledBresenhamLines` in a `VkPhysicalDeviceLineRasterizationFeaturesEXT`
   of the chain, when the device supports both (`GL_LINE_STIPPLE` needs them, and with them
   every line is GL's aliased line), with `VK_EXT_line_rasterization` listed. As with the
   provoking-vertex struct, chain one whatever the device: ffvk takes it out of the chain
   where the device lacks the extension or either feature;
 - `nonSeamlessCubeMap` in a `VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT` of the chain,
   when the device supports it, with `VK_EXT_non_seamless_cube_map` listed
   (`FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP`: the caller's cube map samplers may then take
   `VK_SAMPLER_CREATE_NON_SEAMLESS_CUBE_MAP_BIT_EXT`, filtering each face on its own as GL 2.1
   does). Chain one whatever the device, as above: ffvk takes it out of the chain where the
   device lacks the extension or the feature.

 `extension_names` receives the extensions to enable (static strings, valid for the life of
 the program), to be appended to the caller's own: `*extension_count` is, on the way in, the
 room at `extension_names`, and on the way out how many names ffvk needs (never more than
 `FFVK_MAX_DEVICE_EXTENSIONS`). With `extension_names` null, only the counts and
 `*enabled_features` are written (nothing else changes). `*enabled_features` receives the
 `FFVK_FEATURE_*` bits the created device will have: what `FfvkRendererCreateInfo::
 enabled_features` then says. On success, `ffvkResultMessage()` says which optional features
 are missing, why, and what ffvk refuses without them (`""` when none is).

 Errors: `FFVK_ERROR_INVALID_ARGUMENT` (a null or misaligned pointer or handle, `features`
 not a `VkPhysicalDeviceFeatures2`, a chain without a struct for `dynamicRendering`, a chain
 of more than 64 structs, room for fewer names than needed: `*extension_count` then says how
 many, and nothing else changes); `FFVK_ERROR_MISSING_FEATURE` (a device older than Vulkan
 1.3 or without `dynamicRendering`: nothing changes); `FFVK_ERROR_VULKAN` (listing the
 device's extensions failed).

 # Safety

 `get_instance_proc_addr` is the caller's loader entry point, `instance` a live instance
 created with `apiVersion` 1.3 or later and `physical_device` one of its devices; `features`
 is null or a valid, writable `VkPhysicalDeviceFeatures2` whose `pNext` chain holds valid,
 writable Vulkan structs; `extension_count` and `enabled_features` are null or writable;
 `extension_names` is null or has room for `*extension_count` pointers.
 */
enum FfvkResult ffvkDeviceRequirements(PFN_vkGetInstanceProcAddr get_instance_proc_addr,
                                       VkInstance instance,
                                       VkPhysicalDevice physical_device,
                                       VkPhysicalDeviceFeatures2 *features,
                                       uint32_t *extension_count,
                                       const char **extension_names,
                                       uint32_t *enabled_features);

/*
 The shader library's interface version (`FFVK_LIBRARY_VERSION` in `ffvk/state.glsl`): a
 change of the state block, a function's inputs or outputs, a specialization constant or
 what the caller defines is a new version.
 */
uint32_t ffvkShaderLibraryVersion(void);

/*
 Writes the text of the library file `name` (as a shader includes it: `"ffvk/lighting.glsl"`)
 to `*source` and its length in bytes to `*length`. The text is ffvk's, valid for the life
 of the process, and not NUL-terminated. `FFVK_ERROR_INVALID_ARGUMENT` for a null or
 misaligned pointer and for a name the library does not have (the message lists its files);
 `*source` is then null and `*length` 0.

 # Safety

 `name` is null or a NUL-terminated string; `source` and `length` are null or writable.
 */
enum FfvkResult ffvkShaderLibraryFile(const char *name, const char **source, uintptr_t *length);

/*
 Writes the shader library's state block (`FFVK_STATE_MEMBERS` in `ffvk/state.glsl`, std140)
 for `ctx`'s state under its projection: 3,488 bytes at `dst`, 4-byte aligned. `size` is the
 space at `dst`; less than the block is `FFVK_ERROR_INVALID_ARGUMENT`, as a state GL could not
 draw (the message says why: a positional light with all-zero attenuation, ...).

 # Safety

 `ctx` is null or a live context; `dst` is null or `size` writable bytes.
 */
enum FfvkResult ffvkPackStateBlock(const struct FfvkContext *ctx, void *dst, uintptr_t size);

/*
 Writes a draw's own values for `ctx`'s state and modelview (its materials, current color,
 normal matrix and the rescale factor: `DrawRecord`, 352 bytes) at `dst`, 4-byte aligned:
 what `face_material` and `eye_normal` take, in the layout ffvk's own pipelines read. A
 modelview that cannot be inverted while lighting is `FFVK_ERROR_INVALID_ARGUMENT`.

 # Safety

 `ctx` is null or a live context; `dst` is null or `size` writable bytes.
 */
enum FfvkResult ffvkPackDrawRecord(const struct FfvkContext *ctx, void *dst, uintptr_t size);

/*
 Writes the specialization constants of `ctx`'s state and modelview (`SpecKey`: constant i,
 a 32-bit value, at byte 4i; 49 of them) at `dst`: the data of a `VkSpecializationInfo`
 whose map entries take constant i to the caller's ID `FFVK_SPEC_BASE + i`.

 # Safety

 `ctx` is null or a live context; `dst` is null or `size` writable bytes.
 */
enum FfvkResult ffvkPackSpecKey(const struct FfvkContext *ctx, void *dst, uintptr_t size);

/*
 Writes the specialization constants of a pipeline of the caller's own that draws `mode`
 (GL's primitive: `GL_POINTS` for any pipeline that rasterizes points, polygons in
 `GL_POINT` mode included) into a color attachment of `colorFormat`, with a complete 2D
 texture bound on the units `bound2d` names and a cube map on those `boundCube` names (a bit
 per unit), under `ctx`'s state and modelview: `ffvkPackSpecKey`'s values with the
 pipeline's own set as ffvk sets them in its own pipelines (the point constants from
 `glPointSize` and `glPointParameter`, the target's alpha bits, the units sampled and
 applied). Same layout and errors as `ffvkPackSpecKey`; a `mode` that is not one of GL's
 ten primitive modes, or a bit of `bound2d` or `boundCube` past the last unit, is
 `FFVK_ERROR_INVALID_ARGUMENT`.

 # Safety

 `ctx` is null or a live context; `dst` is null or `size` writable bytes.
 */
enum FfvkResult ffvkPackSpecKeyForPipeline(const struct FfvkContext *ctx,
                                           uint32_t mode,
                                           VkFormat color_format,
                                           uint32_t bound2d,
                                           uint32_t bound_cube,
                                           void *dst,
                                           uintptr_t size);

/*
 Writes `source` with each `#include "ffvk/..."` replaced by the library file's text (each
 file once; other `#include` lines left as they are), for a compiler without `#include`
 (GLSL ES: `ffvk/es.glsl`). `source` is NUL-terminated; the result is written to `dst`, NUL
 included, where `capacity` bytes fit it, and its length without the NUL to `*length` in any
 case, so that a first call with `dst` null and `capacity` 0 asks for the size.
 `FFVK_ERROR_INVALID_ARGUMENT` for a null `source` or `length`, an include the library does
 not have (the message names its line and lists the files), a malformed `#include`, and a
 `capacity` too small for the text and its NUL (nothing is then written to `dst`).

 # Safety

 `source` is null or a NUL-terminated string; `dst` is null or `capacity` writable bytes;
 `length` is null or writable.
 */
enum FfvkResult ffvkShaderLibraryResolve(const char *source,
                                         char *dst,
                                         uintptr_t capacity,
                                         uintptr_t *length);

/*
 Writes to `*viewport` the `VkViewport` that puts ffvk's draws where GL's
 `glViewport(x, y, width, height)` and `glDepthRange(near_val, far_val)` put them, in a
 color attachment `target_height` pixels high. Set it with `vkCmdSetViewport` between
 scopes, as GL's state changes. GL counts window rows from the bottom and Vulkan from the
 top: the result is `x`, `target_height - y - height`, `width`, `height` (positive: ffvk's
 shaders turn GL's clip space into Vulkan's themselves, so there is no negative-height flip)
 and depths `near_val`, `far_val`, clamped to [0, 1] as GL clamps them (near may exceed
 far, as in GL). A layer clamps `width` and `height` to the device's
 `maxViewportDimensions` first, as GL clamps them to `GL_MAX_VIEWPORT_DIMS`.

 Errors (`FFVK_ERROR_INVALID_ARGUMENT`, `*viewport` unchanged): a null or misaligned
 `viewport`; a negative `width` or `height` (GL's `GL_INVALID_VALUE`, which keeps the old
 viewport); a `width` or `height` of 0 (GL draws nothing through an empty viewport, but a
 `VkViewport` cannot be empty: skip the draws instead); a NaN depth; a `target_height` past
 `INT32_MAX`.

 # Safety

 `viewport` is null or writable.
 */
enum FfvkResult ffvkViewport(int32_t x,
                             int32_t y,
                             int32_t width,
                             int32_t height,
                             uint32_t target_height,
                             double near_val,
                             double far_val,
                             VkViewport *viewport);

/*
 Writes to `*scissor` the `VkRect2D` that keeps the pixels GL's
 `glScissor(x, y, width, height)` keeps, in a color attachment of `target_width` x
 `target_height` pixels: GL's rows `y` .. `y + height` from the bottom are rows
 `target_height - y - height` .. `target_height - y` from the top. The box is clipped to the
 target as GL's window clips it, so the result is always a rectangle Vulkan accepts
 (offsets from 0, no overflow); a box outside the target or of width or height 0 is an empty
 rectangle, which draws nothing, as in GL. While `GL_SCISSOR_TEST` is off, GL's box is the
 whole target: pass 0, 0, `target_width`, `target_height`.

 Errors (`FFVK_ERROR_INVALID_ARGUMENT`, `*scissor` unchanged): a null or misaligned
 `scissor`; a negative `width` or `height` (GL's `GL_INVALID_VALUE`); a target side past
 `INT32_MAX`.

 # Safety

 `scissor` is null or writable.
 */
enum FfvkResult ffvkScissor(int32_t x,
                            int32_t y,
                            int32_t width,
                            int32_t height,
                            uint32_t target_width,
                            uint32_t target_height,
                            VkRect2D *scissor);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* FFVK_H */
