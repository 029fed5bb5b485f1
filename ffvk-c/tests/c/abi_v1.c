/* abi_v1.c: a program written against version 1 of ffvk.h (ffvk-c/tests/abi/ffvk_v1.h,
 * frozen), compiled against that header and run with the current library: it creates a
 * renderer and records draws with the struct sizes version 1 declared, enabling its device by
 * hand as version 1's programs did. The test suite (tests/suite/c_api_programs.rs) requires
 * its pixels to be Mesa's GL's for the same scene, and the sizes it prints to be version 1's
 * in the library's table.
 *
 *     abi_v1 SCENE OUTPUT.ppm      (every draw of SCENE covers the whole target) */

#include <stdio.h>
#include <string.h>

#include "ffvk_v1.h"
#include "harness.h"

#define FFVK_CHECK(call)                                                                     \
    do {                                                                                     \
        FfvkResult ffvk_check_result_ = (call);                                              \
        if (ffvk_check_result_ != FFVK_SUCCESS)                                              \
            die("%s:%d: %s: FfvkResult %d: %s", __FILE__, __LINE__, #call,                   \
                (int)ffvk_check_result_, ffvkResultMessage());                               \
    } while (0)

int main(int argc, char **argv) {
    if (argc != 3)
        die("usage: %s SCENE OUTPUT.ppm", argv[0]);
    static Scene scene;
    scene_read(argv[1], &scene);
    for (uint32_t i = 0; i < scene.draw_count; i++) {
        const SceneDraw *d = &scene.draws[i];
        const int32_t whole[4] = {0, 0, (int32_t)scene.width, (int32_t)scene.height};
        if (memcmp(d->viewport, whole, sizeof whole) != 0 ||
            memcmp(d->scissor, whole, sizeof whole) != 0 || d->depth_range[0] != 0.0 ||
            d->depth_range[1] != 1.0)
            die("draw %u does not cover the whole target: version 1 has no ffvkViewport", i);
    }
    printf("sizeof(FfvkRendererCreateInfo) %u\n", (unsigned)sizeof(FfvkRendererCreateInfo));
    printf("sizeof(FfvkDrawInfo) %u\n", (unsigned)sizeof(FfvkDrawInfo));

    App app;
    app_create_instance(&app);
    /* Version 1's way: the features ffvk uses enabled by hand (dynamic rendering, required). */
    VkPhysicalDeviceVulkan13Features v13 = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
        .dynamicRendering = VK_TRUE,
    };
    app_create_device(&app, &v13, 0, NULL);
    app_create_targets(&app, scene.width, scene.height);
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
        .enabled_features = FFVK_FEATURE_DYNAMIC_RENDERING,
        .color_format = COLOR_FORMAT,
        .depth_format = DEPTH_FORMAT,
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

    FFVK_CHECK(ffvkBeginFrame(renderer, 0));
    app_begin(&app, &scene);
    /* Version 1's advice: the whole target as the viewport, a positive height, no flip. */
    VkViewport viewport = {0.0f, 0.0f, (float)scene.width, (float)scene.height, 0.0f, 1.0f};
    VkRect2D scissor = {{0, 0}, {scene.width, scene.height}};
    vkCmdSetViewport(app.cmd, 0, 1, &viewport);
    vkCmdSetScissor(app.cmd, 0, 1, &scissor);
    FFVK_CHECK(ffvkBeginDraws(renderer, app.cmd, 0));
    for (uint32_t i = 0; i < scene.draw_count; i++) {
        const SceneDraw *d = &scene.draws[i];
        ffvkColor4f(ctx, d->color[0], d->color[1], d->color[2], d->color[3]);
        FfvkRaster raster;
        ffvkRasterDefaults(&raster);
        raster.depth_test = 1;
        FfvkDrawInfo draw = {
            .struct_size = sizeof(FfvkDrawInfo),
            .mode = GL_TRIANGLE_FAN,
            .vertex_buffers = &vertices.buffer,
            .vertex_buffer_count = 1,
            .index_buffer = VK_NULL_HANDLE,
            .first = d->first,
            .count = d->count,
            .raster = raster,
        };
        FFVK_CHECK(ffvkDraw(renderer, ctx, &draw));
    }
    FFVK_CHECK(ffvkEndDraws(renderer));
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
