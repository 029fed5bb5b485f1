// GL 2.1 section 3.5.2, polygon stipple: a fragment of a filled polygon is drawn only where
// bit (x_w mod 32) of row (y_w mod 32) of the 32x32 pattern is set, (x_w, y_w) its window
// coordinates, rows counted from the bottom of the framebuffer. Vulkan counts rows from the
// top: with H the framebuffer's height, y_w = H - 1 - y, so only H mod 32 is needed.
// SPEC_STIPPLE is -1 for no stipple (every pipeline but a stippled fill's), else H mod 32; the
// rows hold bit x for column x (least significant bit first). Constants, not uniforms: the
// test never branches on a uniform value.
layout(constant_id = 49) const int SPEC_STIPPLE = -1;
layout(constant_id = 50) const uint SPEC_STIPPLE_ROW_0 = 0xFFFFFFFFu;
layout(constant_id = 51) const uint SPEC_STIPPLE_ROW_1 = 0xFFFFFFFFu;
layout(constant_id = 52) const uint SPEC_STIPPLE_ROW_2 = 0xFFFFFFFFu;
layout(constant_id = 53) const uint SPEC_STIPPLE_ROW_3 = 0xFFFFFFFFu;
layout(constant_id = 54) const uint SPEC_STIPPLE_ROW_4 = 0xFFFFFFFFu;
layout(constant_id = 55) const uint SPEC_STIPPLE_ROW_5 = 0xFFFFFFFFu;
layout(constant_id = 56) const uint SPEC_STIPPLE_ROW_6 = 0xFFFFFFFFu;
layout(constant_id = 57) const uint SPEC_STIPPLE_ROW_7 = 0xFFFFFFFFu;
layout(constant_id = 58) const uint SPEC_STIPPLE_ROW_8 = 0xFFFFFFFFu;
layout(constant_id = 59) const uint SPEC_STIPPLE_ROW_9 = 0xFFFFFFFFu;
layout(constant_id = 60) const uint SPEC_STIPPLE_ROW_10 = 0xFFFFFFFFu;
layout(constant_id = 61) const uint SPEC_STIPPLE_ROW_11 = 0xFFFFFFFFu;
layout(constant_id = 62) const uint SPEC_STIPPLE_ROW_12 = 0xFFFFFFFFu;
layout(constant_id = 63) const uint SPEC_STIPPLE_ROW_13 = 0xFFFFFFFFu;
layout(constant_id = 64) const uint SPEC_STIPPLE_ROW_14 = 0xFFFFFFFFu;
layout(constant_id = 65) const uint SPEC_STIPPLE_ROW_15 = 0xFFFFFFFFu;
layout(constant_id = 66) const uint SPEC_STIPPLE_ROW_16 = 0xFFFFFFFFu;
layout(constant_id = 67) const uint SPEC_STIPPLE_ROW_17 = 0xFFFFFFFFu;
layout(constant_id = 68) const uint SPEC_STIPPLE_ROW_18 = 0xFFFFFFFFu;
layout(constant_id = 69) const uint SPEC_STIPPLE_ROW_19 = 0xFFFFFFFFu;
layout(constant_id = 70) const uint SPEC_STIPPLE_ROW_20 = 0xFFFFFFFFu;
layout(constant_id = 71) const uint SPEC_STIPPLE_ROW_21 = 0xFFFFFFFFu;
layout(constant_id = 72) const uint SPEC_STIPPLE_ROW_22 = 0xFFFFFFFFu;
layout(constant_id = 73) const uint SPEC_STIPPLE_ROW_23 = 0xFFFFFFFFu;
layout(constant_id = 74) const uint SPEC_STIPPLE_ROW_24 = 0xFFFFFFFFu;
layout(constant_id = 75) const uint SPEC_STIPPLE_ROW_25 = 0xFFFFFFFFu;
layout(constant_id = 76) const uint SPEC_STIPPLE_ROW_26 = 0xFFFFFFFFu;
layout(constant_id = 77) const uint SPEC_STIPPLE_ROW_27 = 0xFFFFFFFFu;
layout(constant_id = 78) const uint SPEC_STIPPLE_ROW_28 = 0xFFFFFFFFu;
layout(constant_id = 79) const uint SPEC_STIPPLE_ROW_29 = 0xFFFFFFFFu;
layout(constant_id = 80) const uint SPEC_STIPPLE_ROW_30 = 0xFFFFFFFFu;
layout(constant_id = 81) const uint SPEC_STIPPLE_ROW_31 = 0xFFFFFFFFu;

bool stipple_passes() {
    if (SPEC_STIPPLE < 0) return true;
    uint x = uint(gl_FragCoord.x) & 31u;
    uint y_w = (uint(SPEC_STIPPLE) + 31u - (uint(gl_FragCoord.y) & 31u)) & 31u;
    uint row = 0xFFFFFFFFu;
    switch (y_w) {
        case 0u: row = SPEC_STIPPLE_ROW_0; break;
        case 1u: row = SPEC_STIPPLE_ROW_1; break;
        case 2u: row = SPEC_STIPPLE_ROW_2; break;
        case 3u: row = SPEC_STIPPLE_ROW_3; break;
        case 4u: row = SPEC_STIPPLE_ROW_4; break;
        case 5u: row = SPEC_STIPPLE_ROW_5; break;
        case 6u: row = SPEC_STIPPLE_ROW_6; break;
        case 7u: row = SPEC_STIPPLE_ROW_7; break;
        case 8u: row = SPEC_STIPPLE_ROW_8; break;
        case 9u: row = SPEC_STIPPLE_ROW_9; break;
        case 10u: row = SPEC_STIPPLE_ROW_10; break;
        case 11u: row = SPEC_STIPPLE_ROW_11; break;
        case 12u: row = SPEC_STIPPLE_ROW_12; break;
        case 13u: row = SPEC_STIPPLE_ROW_13; break;
        case 14u: row = SPEC_STIPPLE_ROW_14; break;
        case 15u: row = SPEC_STIPPLE_ROW_15; break;
        case 16u: row = SPEC_STIPPLE_ROW_16; break;
        case 17u: row = SPEC_STIPPLE_ROW_17; break;
        case 18u: row = SPEC_STIPPLE_ROW_18; break;
        case 19u: row = SPEC_STIPPLE_ROW_19; break;
        case 20u: row = SPEC_STIPPLE_ROW_20; break;
        case 21u: row = SPEC_STIPPLE_ROW_21; break;
        case 22u: row = SPEC_STIPPLE_ROW_22; break;
        case 23u: row = SPEC_STIPPLE_ROW_23; break;
        case 24u: row = SPEC_STIPPLE_ROW_24; break;
        case 25u: row = SPEC_STIPPLE_ROW_25; break;
        case 26u: row = SPEC_STIPPLE_ROW_26; break;
        case 27u: row = SPEC_STIPPLE_ROW_27; break;
        case 28u: row = SPEC_STIPPLE_ROW_28; break;
        case 29u: row = SPEC_STIPPLE_ROW_29; break;
        case 30u: row = SPEC_STIPPLE_ROW_30; break;
        case 31u: row = SPEC_STIPPLE_ROW_31; break;
    }
    return ((row >> x) & 1u) != 0u;
}
