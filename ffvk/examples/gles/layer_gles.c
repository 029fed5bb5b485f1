/* The layer example's shaders on OpenGL ES 3 (GLSL ES 3.00): the same layer source and the
 * same library functions as its Vulkan pipelines, with the library's ES header, drawn in an
 * OpenGL ES 3 context through EGL without a surface (Mesa's surfaceless platform).
 *
 *   cc layer_gles.c -lEGL -lGLESv2 -o layer_gles
 *   layer_gles DIR SIZE R G B A
 *   layer_gles --compile vert|frag FILE
 *
 * DIR holds what the layer's Rust side wrote (tests/suite/layer.rs): vert.glsl and frag.glsl
 * (GLSL ES 3.00, the library inlined), draw.bin (the LayerDraw block's std140 bytes),
 * state.bin (FfvkState's), positions.bin (3 floats a vertex), attributes.bin (3 floats of
 * normal and 4 bytes of color a vertex), indices.bin (32-bit). It draws SIZE x SIZE pixels
 * cleared to (R, G, B, A) with GL's depth test and writes DIR/image.rgba, the top row first,
 * and prints GL_RENDERER and GL_VERSION. With --compile it only compiles FILE as a vertex or
 * fragment shader (the guide's snippets). Any failure is a message on stderr and exit 1. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void fail(const char *what, const char *detail) {
    fprintf(stderr, "layer_gles: %s%s%s\n", what, detail ? ": " : "", detail ? detail : "");
    exit(1);
}

/* The whole of DIR/name (name alone where dir is null), NUL-terminated; its length in *length. */
static char *read_file(const char *dir, const char *name, size_t *length) {
    char path[4096];
    snprintf(path, sizeof path, "%s%s%s", dir ? dir : "", dir ? "/" : "", name);
    FILE *f = fopen(path, "rb");
    if (!f) fail("cannot open", path);
    if (fseek(f, 0, SEEK_END) != 0) fail("cannot seek", path);
    long size = ftell(f);
    if (size < 0) fail("cannot size", path);
    rewind(f);
    char *bytes = malloc((size_t)size + 1);
    if (!bytes) fail("out of memory for", path);
    if (fread(bytes, 1, (size_t)size, f) != (size_t)size) fail("cannot read", path);
    fclose(f);
    bytes[size] = 0;
    *length = (size_t)size;
    return bytes;
}

static GLuint shader(GLenum stage, const char *source, const char *name) {
    GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &source, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        static char log[16384];
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        fail(name, log);
    }
    return s;
}

static GLuint buffer(GLenum target, const void *bytes, size_t length) {
    GLuint b;
    glGenBuffers(1, &b);
    glBindBuffer(target, b);
    glBufferData(target, (GLsizeiptr)length, bytes, GL_STATIC_DRAW);
    return b;
}

/* Binds the program's uniform block `name` to binding point `binding`, holding `bytes`. */
static void block(GLuint program, const char *name, GLuint binding, const char *bytes, size_t length) {
    GLuint index = glGetUniformBlockIndex(program, name);
    if (index == GL_INVALID_INDEX) fail("the program has no uniform block", name);
    GLint size = 0;
    glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    if ((size_t)size > length) {
        char detail[256];
        snprintf(detail, sizeof detail, "%s is %d bytes in the program, %zu given", name, size, length);
        fail("a uniform block's size", detail);
    }
    glUniformBlockBinding(program, index, binding);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding, buffer(GL_UNIFORM_BUFFER, bytes, length));
}

/* An OpenGL ES 3.0 context without a surface on Mesa's surfaceless platform, current. */
static void make_context(EGLDisplay *display_out, EGLContext *context_out) {
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_platform_display) fail("no eglGetPlatformDisplayEXT", NULL);
    EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (display == EGL_NO_DISPLAY) fail("no surfaceless EGL display", NULL);
    if (!eglInitialize(display, NULL, NULL)) fail("eglInitialize failed", NULL);
    if (!eglBindAPI(EGL_OPENGL_ES_API)) fail("eglBindAPI(EGL_OPENGL_ES_API) failed", NULL);
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_NONE};
    EGLConfig config;
    EGLint configs = 0;
    if (!eglChooseConfig(display, wanted, &config, 1, &configs) || configs < 1)
        fail("no EGLConfig renders OpenGL ES 3", NULL);
    const EGLint version[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, version);
    if (context == EGL_NO_CONTEXT) fail("eglCreateContext (OpenGL ES 3.0) failed", NULL);
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
        fail("eglMakeCurrent without a surface failed", NULL);
    printf("GL_RENDERER %s\nGL_VERSION %s\n", (const char *)glGetString(GL_RENDERER),
           (const char *)glGetString(GL_VERSION));
    *display_out = display;
    *context_out = context;
}

int main(int argc, char **argv) {
    EGLDisplay display;
    EGLContext context;
    size_t length;
    if (argc == 4 && strcmp(argv[1], "--compile") == 0) {
        int vertex = strcmp(argv[2], "vert") == 0;
        if (!vertex && strcmp(argv[2], "frag") != 0) fail("--compile takes vert or frag, not", argv[2]);
        make_context(&display, &context);
        char *text = read_file(NULL, argv[3], &length);
        shader(vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER, text, argv[3]);
        return 0;
    }
    if (argc != 7) fail("usage", "layer_gles DIR SIZE R G B A, or layer_gles --compile vert|frag FILE");
    const char *dir = argv[1];
    int size = atoi(argv[2]);
    if (size <= 0 || size > 4096) fail("SIZE must be 1 to 4096, not", argv[2]);
    float clear[4];
    for (int i = 0; i < 4; i++) clear[i] = strtof(argv[3 + i], NULL);
    make_context(&display, &context);

    char *vert = read_file(dir, "vert.glsl", &length);
    char *frag = read_file(dir, "frag.glsl", &length);
    GLuint program = glCreateProgram();
    glAttachShader(program, shader(GL_VERTEX_SHADER, vert, "vert.glsl"));
    glAttachShader(program, shader(GL_FRAGMENT_SHADER, frag, "frag.glsl"));
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        static char log[16384];
        glGetProgramInfoLog(program, sizeof log, NULL, log);
        fail("linking", log);
    }
    glUseProgram(program);
    char *bytes = read_file(dir, "draw.bin", &length);
    block(program, "LayerDraw", 0, bytes, length);
    bytes = read_file(dir, "state.bin", &length);
    block(program, "FfvkState", 1, bytes, length);

    /* The teapot: positions (location 0), normals and 8-bit colors (1, 2), 32-bit indices. */
    GLuint vao;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    bytes = read_file(dir, "positions.bin", &length);
    buffer(GL_ARRAY_BUFFER, bytes, length);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 12, (const void *)0);
    glEnableVertexAttribArray(0);
    bytes = read_file(dir, "attributes.bin", &length);
    buffer(GL_ARRAY_BUFFER, bytes, length);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 16, (const void *)0);
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, 16, (const void *)12);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(2);
    bytes = read_file(dir, "indices.bin", &length);
    buffer(GL_ELEMENT_ARRAY_BUFFER, bytes, length);
    GLsizei count = (GLsizei)(length / 4);

    /* RGBA8 color and 32-bit float depth, as the Vulkan side's attachments. */
    GLuint fbo, color, depth;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size, size);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, size, size);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) fail("incomplete framebuffer", NULL);

    glViewport(0, 0, size, size);
    glClearColor(clear[0], clear[1], clear[2], clear[3]);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, (const void *)0);
    GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
        char detail[32];
        snprintf(detail, sizeof detail, "0x%04x", error);
        fail("a GL error", detail);
    }

    /* glReadPixels reads the bottom row first: written top row first. */
    size_t row = (size_t)size * 4;
    unsigned char *pixels = malloc(row * (size_t)size);
    if (!pixels) fail("out of memory for the image", NULL);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    char path[4096];
    snprintf(path, sizeof path, "%s/image.rgba", dir);
    FILE *out = fopen(path, "wb");
    if (!out) fail("cannot write", path);
    for (int y = size - 1; y >= 0; y--) {
        if (fwrite(pixels + (size_t)y * row, 1, row, out) != row) fail("cannot write", path);
    }
    if (fclose(out) != 0) fail("cannot write", path);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    eglTerminate(display);
    return 0;
}
