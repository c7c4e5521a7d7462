#include "samples/viewer/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

namespace agaa::viewer {
namespace {

// GLFW reports failures through this callback before returning an error value; keep the last
// one so the WindowError can say why (e.g. "X11: The DISPLAY environment variable is missing").
std::string g_lastGlfwError;

void onGlfwError(int code, const char* description) {
    g_lastGlfwError = std::string(description ? description : "unknown error") + " (GLFW error " +
                      std::to_string(code) + ")";
}

std::string lastError() {
    return g_lastGlfwError.empty() ? std::string("no reason given") : g_lastGlfwError;
}

} // namespace

Window::Window(uint32_t width, uint32_t height, const std::string& title) {
    glfwSetErrorCallback(&onGlfwError);
    if (glfwInit() != GLFW_TRUE)
        throw WindowError("cannot initialise GLFW: " + lastError() +
                          ". The viewer needs a display (X11 or Wayland); for a headless check run it under "
                          "xvfb-run");
    if (glfwVulkanSupported() != GLFW_TRUE) {
        std::string why = lastError();
        glfwTerminate();
        throw WindowError("GLFW finds no Vulkan loader: " + why +
                          " (install libvulkan1 and mesa-vulkan-drivers)");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API); // Vulkan presents; no GL context
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    m_window = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!m_window) {
        std::string why = lastError();
        glfwTerminate();
        throw WindowError("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                          " window: " + why);
    }
    glfwSetWindowUserPointer(m_window, this);
    glfwSetKeyCallback(m_window, &Window::onKey);
    glfwSetCursorPosCallback(m_window, &Window::onCursor);
    glfwSetMouseButtonCallback(m_window, &Window::onButton);
    glfwSetScrollCallback(m_window, &Window::onScroll);
    glfwSetFramebufferSizeCallback(m_window, &Window::onResize);
    glfwGetCursorPos(m_window, &m_cursorX, &m_cursorY);
}

Window::~Window() {
    if (m_window) glfwDestroyWindow(m_window);
    glfwTerminate();
}

std::vector<const char*> Window::requiredInstanceExtensions() const {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names)
        throw WindowError("GLFW reports no Vulkan surface extensions for this display: " + lastError());
    return std::vector<const char*>(names, names + count);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VkResult result = glfwCreateWindowSurface(instance, m_window, nullptr, &surface);
    if (result != VK_SUCCESS)
        throw WindowError("cannot create a Vulkan surface for the window (VkResult " +
                          std::to_string(result) + "): " + lastError());
    return surface;
}

bool Window::shouldClose() const {
    return glfwWindowShouldClose(m_window) == GLFW_TRUE;
}

void Window::requestClose() {
    glfwSetWindowShouldClose(m_window, GLFW_TRUE);
}

void Window::pollEvents() {
    glfwPollEvents();
}

void Window::waitEvents() {
    glfwWaitEvents();
}

VkExtent2D Window::framebufferSize() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(m_window, &width, &height);
    return {uint32_t(width > 0 ? width : 0), uint32_t(height > 0 ? height : 0)};
}

bool Window::minimised() const {
    const VkExtent2D size = framebufferSize();
    return glfwGetWindowAttrib(m_window, GLFW_ICONIFIED) == GLFW_TRUE || size.width == 0 || size.height == 0;
}

void Window::setTitle(const std::string& title) {
    glfwSetWindowTitle(m_window, title.c_str());
}

InputEvents Window::takeInput() {
    InputEvents input = std::move(m_input);
    m_input = InputEvents{};
    return input;
}

Window& Window::self(GLFWwindow* window) {
    return *static_cast<Window*>(glfwGetWindowUserPointer(window));
}

void Window::onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action == GLFW_PRESS) self(window).m_input.keys.push_back(key);
}

void Window::onCursor(GLFWwindow* window, double x, double y) {
    Window& w = self(window);
    if (w.m_dragging) {
        w.m_input.dragX += x - w.m_cursorX;
        w.m_input.dragY += y - w.m_cursorY;
    }
    w.m_cursorX = x;
    w.m_cursorY = y;
}

void Window::onButton(GLFWwindow* window, int button, int action, int) {
    if (button == GLFW_MOUSE_BUTTON_LEFT) self(window).m_dragging = action == GLFW_PRESS;
}

void Window::onScroll(GLFWwindow* window, double, double dy) {
    self(window).m_input.scroll += dy;
}

void Window::onResize(GLFWwindow* window, int, int) {
    self(window).m_input.resized = true;
}

} // namespace agaa::viewer
