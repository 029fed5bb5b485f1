/* raster.c: a scene drawn through ffvk's C API with version 3 draws that take GL's raster
 * state from the context (FFVK_RASTER_SOURCE_CONTEXT), set before each draw with the C entry
 * points GL's calls name: ffvkColorMask, ffvkEnable(GL_STENCIL_TEST) with ffvkStencilFunc and
 * ffvkStencilOp, ffvkEnable(GL_COLOR_LOGIC_OP) with ffvkLogicOp, and the depth test
 * (glEnable(GL_DEPTH_TEST), GL_LESS), on a D24_UNORM_S8_UINT depth-stencil target and a device
 * made with ffvkDeviceRequirements (with logicOp, which GL_COLOR_LOGIC_OP needs). The test
 * suite (tests/suite/c_api_programs.rs) draws the same scene with Mesa's GL and requires the
 * same pixels, and the values GL's spec gives.
 *
 *     raster SCENE OUTPUT.ppm */

#include <stdio.h>
#include <string.h>

#include "ffvk.h"
#include "harness.h"

#define FFVK_CHECK(call)                                                                     \
    do {                                                                                     \
        FfvkResult ffvk_check_result_ = (call);                                              \
        if (ffvk_check_result_ != FFVK_SUCCESS)                                              \
            die("%s:%d: %s: FfvkResult %d: %s", __FILE__, __LINE__, #call,                   \
                (int)ffvk_check_result_, ffvkResultMessage());                               \
    } while (0)

/* Enables or disables `cap` as `on` says. */
static void set_cap(FfvkContext *ctx, uint32_t cap, uint32_t on) {
    if (on)
        ffvkEnable(ctx, cap);
    else
        ffvkDisable(ctx, cap);
}

int main(int argc, char **argv) {
    if (argc != 3)
        die("usage: %s SCENE OUTPUT.ppm", argv[0]);
    static Scene scene;
    scene_read(argv[1], &scene);

    App app;
    app_create_instance(&app);
    VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT non_seamless = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_NON_SEAMLESS_CUBE_MAP_FEATURES_EXT,
    };
    VkPhysicalDeviceLineRasterizationFeaturesEXT lines = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT,
        .pNext = &non_seamless,
    };
    VkPhysicalDeviceProvokingVertexFeaturesEXT provoking = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT,
        .pNext = &lines,
    };
    VkPhysicalDeviceVulkan13Features v13 = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
        .pNext = &provoking,
    };
    VkPhysicalDeviceFeatures2 features = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
        .pNext = &v13,
    };
    const char *extensions[FFVK_MAX_DEVICE_EXTENSIONS];
    uint32_t extension_count = FFVK_MAX_DEVICE_EXTENSIONS;
    uint32_t enabled_features;
    FFVK_CHECK(ffvkDeviceRequirements(vkGetInstanceProcAddr, app.instance, app.physical,
                                      &features, &extension_count, extensions,
                                      &enabled_features));
    /* lavapipe has every optional feature: the test is about drawing with them. */
    if (ffvkResultMessage()[0] != '\0')
        die("the device lacks what the scene needs: %s", ffvkResultMessage());
    const uint32_t wanted = FFVK_FEATURE_FILL_MODE_NON_SOLID | FFVK_FEATURE_LOGIC_OP |
                            FFVK_FEATURE_STIPPLED_LINES;
    if ((enabled_features & wanted) != wanted || features.features.logicOp != VK_TRUE ||
        lines.stippledBresenhamLines != VK_TRUE || extension_count != 3)
        die("ffvkDeviceRequirements: enabled_features 0x%X, logicOp %u, "
            "stippledBresenhamLines %u, %u extension(s)",
            enabled_features, features.features.logicOp, lines.stippledBresenhamLines,
            extension_count);
    app_create_device(&app, &features, extension_count, extensions);
    app_create_targets_with(&app, scene.width, scene.height, VK_FORMAT_D24_UNORM_S8_UINT);
    Buffer vertices = app_buffer(&app, scene.vertices, sizeof scene.vertices,
                                 VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);

    const VkVertexInputBindingDescription binding = {
        .binding = 0, .stride = 24, .inputRate = VK_VERTEX_INPUT_RATE_VERTEX};
    FfvkRendererCreateInfo info = {
        .struct_size = sizeof(FfvkRendererCreateInfo),
        .get_instance_proc_addr = vkGetInstanceProcAddr,
        .instance = app.instance,
        .physical_device = app.physical,
        .device = app.device,
        .enabled_features = enabled_features,
        .color_format = COLOR_FORMAT,
        .depth_format = VK_FORMAT_D24_UNORM_S8_UINT,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        .bindings = &binding,
        .binding_count = 1,
        .position = {.binding = 0, .offset = 0, .format = VK_FORMAT_R32G32B32_SFLOAT},
        .normal = {.binding = 0, .offset = 12, .format = VK_FORMAT_R32G32B32_SFLOAT},
        .frames_in_flight = 1,
    };
    FfvkRenderer *renderer;
    FFVK_CHECK(ffvkCreateRenderer(&info, &renderer));
    FfvkContext *ctx = ffvkCreateContext();
    if (!ctx)
        die("ffvkCreateContext failed");
    /* glEnable(GL_DEPTH_TEST): GL_LESS, GL's initial function. */
    ffvkEnable(ctx, GL_DEPTH_TEST);

    FFVK_CHECK(ffvkBeginFrame(renderer, 0));
    app_begin(&app, &scene);
    for (uint32_t i = 0; i < scene.draw_count; i++) {
        const SceneDraw *d = &scene.draws[i];
        VkViewport viewport;
        VkRect2D scissor;
        FFVK_CHECK(ffvkViewport(d->viewport[0], d->viewport[1], d->viewport[2], d->viewport[3],
                                scene.height, d->depth_range[0], d->depth_range[1],
                                &viewport));
        FFVK_CHECK(ffvkScissor(d->scissor[0], d->scissor[1], d->scissor[2], d->scissor[3],
                               scene.width, scene.height, &scissor));
        vkCmdSetViewport(app.cmd, 0, 1, &viewport);
        vkCmdSetScissor(app.cmd, 0, 1, &scissor);

        /* The GL calls of this draw's raster state, on the context. */
        const SceneRaster *r = &d->raster;
        ffvkColorMask(ctx, (uint8_t)r->color_mask[0], (uint8_t)r->color_mask[1],
                      (uint8_t)r->color_mask[2], (uint8_t)r->color_mask[3]);
        set_cap(ctx, GL_STENCIL_TEST, r->stencil_test);
        ffvkStencilFunc(ctx, r->stencil_func, (int32_t)r->stencil_ref, r->stencil_mask);
        ffvkStencilOp(ctx, r->stencil_ops[0], r->stencil_ops[1], r->stencil_ops[2]);
        set_cap(ctx, GL_COLOR_LOGIC_OP, r->logic_op_enabled);
        ffvkLogicOp(ctx, r->logic_op);
        ffvkColor4f(ctx, d->color[0], d->color[1], d->color[2], d->color[3]);
        uint32_t error = ffvkGetError(ctx);
        if (error != 0)
            die("draw %u: GL error 0x%04X setting its raster state", i, error);

        /* The draw's own raster (defaults) is not read: the context's state is. */
        FfvkRaster raster;
        ffvkRasterDefaults(&raster);
        FfvkDrawInfo draw = {
            .struct_size = sizeof(FfvkDrawInfo),
            .mode = GL_TRIANGLE_FAN,
            .vertex_buffers = &vertices.buffer,
            .vertex_buffer_count = 1,
            .index_buffer = VK_NULL_HANDLE,
            .first = d->first,
            .count = d->count,
            .raster = raster,
            .raster_source = FFVK_RASTER_SOURCE_CONTEXT,
        };
        FFVK_CHECK(ffvkBeginDraws(renderer, app.cmd, 0));
        FFVK_CHECK(ffvkDraw(renderer, ctx, &draw));
        FFVK_CHECK(ffvkEndDraws(renderer));
    }
    app_finish(&app, argv[2]);

    VkResult idle = vkDeviceWaitIdle(app.device);
    if (idle != VK_SUCCESS)
        die("vkDeviceWaitIdle: VkResult %d", (int)idle);
    ffvkDestroyRenderer(renderer);
    ffvkDestroyContext(ctx);
    app_destroy_buffer(&app, &vertices);
    unsigned messages = app_destroy(&app);
    if (messages > 0)
        die("%u validation message(s)", messages);
    return 0;
}
