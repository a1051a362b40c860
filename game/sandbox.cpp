#include "game/sandbox.h"

#include <GLFW/glfw3.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <imgui.h>
#include <map>
#include <memory>
#include <optional>
#include <thread>

#include "core/atomic_file.h"
#include "game/autosave.h"
#include "game/background_saver.h"
#include "game/camera_controller.h"
#include "game/edit_tools.h"
#include "game/hud.h"
#include "game/imgui_platform.h"
#include "game/input.h"
#include "game/object_tools.h"
#include "game/render_scale_controller.h"
#include "game/script_player.h"
#include "game/streamed_world.h"
#include "game/undo_history.h"
#include "game/walk_controller.h"
#include "game/window.h"
#include "game/world_file_stem.h"
#include "game/world_store.h"
#include "gpu/context.h"
#include "gpu/presenter.h"
#include "io/image_io.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "scene/generators/store_keys.h"
#include "scene/scene_file.h"
#include "scene/scene_lighting.h"

namespace game {

namespace fs = std::filesystem;
namespace world = engine::world;

std::string noDisplayMessage(const std::string& why, bool captureCommand) {
    return fmt::format(
        "vox play: {}; the sandbox needs a window. Render headless instead: "
        "`vox render [WORLD] -o out/render.png`{}",
        why, captureCommand ? " (or `vox capture` for scripted flythroughs)" : "");
}

namespace {

constexpr float kScriptStep = 1.0f / 30.0f;  // seconds per frame while a script plays
constexpr float kMinRenderScale = 1.0f / 16.0f;
constexpr double kMessageSeconds = 4.0;
constexpr const char* kSavedViewName = "saved view";

class Sandbox {
public:
    explicit Sandbox(const PlayOptions& options)
        : mOptions(options),
          mWalk(options.player),
          mUndo(options.undoMegabytes << 20),
          mAutosave(options.autosaveMinutes * 60.0) {}
    int run();

private:
    engine::Status init();
    // What renderFrame() did: `presented` false when the window is minimised.
    struct RenderedFrame {
        engine::render::FrameResult result;
        bool presented = false;
        double renderCallMs = 0.0;
        glm::uvec2 size{0};
    };

    void frame();
    float advanceClock(std::chrono::steady_clock::time_point start);
    void pollInput();
    void applyHudActions(const HudActions& actions);
    void requestScriptCaptures();
    RenderedFrame renderFrame(glm::uvec2 framebuffer);
    void adjustRenderScale(double frameMs, glm::uvec2 framebuffer);
    void handleInput(float dt);
    void handleEditClicks();
    void handleToolKeys(bool hudMouse, bool clickCaptured);
    void handleQuitPrompt();
    void applyEdit(const EditOp& op);
    void handleObjects(bool clicks);
    void undo();
    void redo();
    // Queues a save (game/background_saver.h); `wait` blocks until it is on disk (quitting).
    engine::Status save(const fs::path& path, bool autosave, bool wait = false);
    // Reports the saves finished since the last call; returns the last failure, if any (a failed
    // save is not reported with `quiet`: the caller says it).
    engine::Status pollSaves(bool quiet = false);
    void updateStreaming();
    bool streamedBoxMissing(const world::Box& voxels) const {
        return mStreaming && !mStreaming->boxInGrid(voxels);
    }
    void requestQuit();
    void setMouseLook(bool on);
    void message(std::string text);
    void afterFrame(const engine::render::FrameResult& result, bool presented);
    void runScriptActions();
    void writeRenderImage(const fs::path& path);
    void writeWindowCapture(const fs::path& path);
    void logView(const char* what, const fs::path& path);
    HudStats hudStats();
    glm::uvec2 renderSize(glm::uvec2 framebuffer) const;
    std::string title() const;
    // A save being written counts as saved; if it fails, the world is unsaved again.
    bool unsaved() const {
        return mWorldVersion != mSavedVersion && mPendingSaveVersion != mWorldVersion;
    }

    PlayOptions mOptions;
    world::Scene mScene;
    fs::path mWorldPath, mSavePath;
    std::unique_ptr<WorldStore> mStore = makeWorldStore();
    BackgroundSaver mSaver;
    // Streaming (game/streamed_world.h): the grid holds only the regions near the camera. An
    // edited region is pinned (kept in memory) until its save commits: edited after
    // mCommittedEpoch, or touched by the undo history.
    std::unique_ptr<world::GridStreaming> mStreaming;
    fs::path mStreamStore;  // the store it streams from; empty: a generated terrain
    std::uint32_t mCommittedEpoch = 0;
    std::map<std::uint64_t, std::uint32_t> mSaveEpochs;  // world version -> its save's epoch
    std::uint64_t mPinnedVersion = ~std::uint64_t(0);
    std::uint32_t mPinnedEpoch = 0;
    world::GridStreamingReport mStreamReport;
    bool mStreamWait = false;  // the player waits for the regions around it
    std::size_t mPeakStreamRegions = 0;
    std::uint64_t mPeakStreamBytes = 0;

    // Declaration order is destruction order reversed: the presenter needs the ImGui context
    // and the device, and the device's surface needs the window.
    std::unique_ptr<Window> mWindow;
    std::unique_ptr<engine::gpu::Context> mCtx;
    std::unique_ptr<ImGuiPlatform> mImGui;
    std::unique_ptr<engine::gpu::Presenter> mPresenter;
    std::unique_ptr<engine::render::Renderer> mRenderer;

    std::optional<ScriptPlayer> mScript;
    InputState mInput;
    CameraController mCamera;
    WalkController mWalk;
    EditTools mTools;
    ObjectTools mObjects;
    UndoHistory mUndo;
    Autosave mAutosave;
    Hud mHud;
    // The edit and frame logs are journals: appended and flushed line by line so a session that
    // crashes or is stopped early keeps its rows (a long streaming flight is measured even if it
    // is killed), and checked at exit.
    std::ofstream mEditLog;
    std::ofstream mFrameLog;
    engine::AtomicFile mWalkLogFile;
    std::ostream* mWalkLog = nullptr;

    std::uint64_t mFrame = 0;
    double mTime = 0.0;  // seconds: the script clock, or wall clock since start
    std::chrono::steady_clock::time_point mLastFrameStart;
    double mCpuFrameMs = 0.0;
    engine::render::FrameResult mLastFrame;
    float mRenderScale = 0.25f;
    bool mAutoScale = false;
    RenderScaleController mScaleController{90.0, kMinRenderScale, 1.0f};
    float mExposure = 1.0f;
    std::size_t mCameraIndex = 0;
    bool mMouseLook = false;
    bool mQuit = false;
    bool mQuitPrompt = false;

    std::uint64_t mWorldVersion = 0, mSavedVersion = 0;
    std::optional<std::uint64_t> mPendingSaveVersion;
    engine::lighting::LightingSettings mLighting;
    Pick mTarget;

    // Edits applied this frame, reported with the upload counter once the frame is presented.
    std::size_t mFrameEdits = 0, mFrameChangedCells = 0;
    std::string mMessage;
    StoreStatus mStoreStatus;  // the save's store, for the HUD: read at start, then from saves
    double mMessageTime = -1e9;
    bool mCaptureRequested = false;
    fs::path mPendingCapturePath, mPendingRenderPath;
    std::string mTitle;
};

glm::uvec2 Sandbox::renderSize(glm::uvec2 framebuffer) const {
    glm::vec2 s = glm::round(glm::vec2(framebuffer) * mRenderScale);
    return glm::max(glm::uvec2(s), glm::uvec2(1));
}

std::string Sandbox::title() const {
    return fmt::format("vox play - {}{}", mScene.name, unsaved() ? " (unsaved)" : "");
}

void Sandbox::message(std::string text) {
    std::printf("frame %llu: %s\n", static_cast<unsigned long long>(mFrame), text.c_str());
    std::fflush(stdout);
    mMessage = std::move(text);
    mMessageTime = mTime;
}

engine::Status Sandbox::init() {
    mRenderScale = std::clamp(mOptions.renderScale, kMinRenderScale, 1.0f);
    mAutoScale = mOptions.autoScale && mOptions.scriptPath.empty();  // scripts repeat exactly
    mScaleController = RenderScaleController(mOptions.targetFrameMs, kMinRenderScale, 1.0f);
    if (!mOptions.scriptPath.empty()) {
        auto script = ScriptPlayer::load(mOptions.scriptPath);
        if (!script) return script.error();
        mScript = std::move(*script);
    }
    auto path =
        engine::scene::resolveWorldPath(mOptions.world.empty() ? "sandbox" : mOptions.world);
    if (!path) return path.error();
    mWorldPath = *path;
    auto streamed = openStreamedWorld(mWorldPath, mOptions.stream);
    if (!streamed) return streamed.error();
    if (*streamed) {
        mScene = std::move((*streamed)->scene);
        mStreaming = std::move((*streamed)->streaming);
        mStreamStore = (*streamed)->store;
        mSaver.setPartialGrid(true);
    } else {
        auto scene = mStore->load(mWorldPath);
        if (!scene) return scene.error();
        mScene = std::move(*scene);
    }
    // A world read whole from a store saves back to it incrementally (a streamed one: only into
    // it).
    if (fs::path store = engine::scene::storeOfScene(mScene); !store.empty())
        mSaver.worldLoaded(mScene, store);
    mCommittedEpoch = mScene.grid.editEpoch() - 1;
    if (!mOptions.camera.empty()) {
        bool found =
            std::any_of(mScene.cameras.begin(), mScene.cameras.end(),
                        [&](const world::CameraPreset& c) { return c.name == mOptions.camera; });
        if (!found)
            return engine::makeError("{}: no camera named '{}'", mWorldPath.string(),
                                     mOptions.camera);
    }
    mCamera.setFromPreset(mScene.camera(mOptions.camera));
    for (std::size_t i = 0; i < mScene.cameras.size(); ++i) {
        if (mScene.cameras[i].name == mCamera.preset().name) mCameraIndex = i;
    }
    // A world of [world] alone (or a colourless .vox) has no material to place with: none is
    // chosen, and placing and painting are refused until it has one (an object's model brings its
    // own).
    mTools.material = mScene.palette.size() > 1 ? 1 : world::kEmpty;
    for (const std::string& m : mOptions.models) {
        auto modelPath = engine::scene::resolveWorldPath(m);
        if (!modelPath) return modelPath.error();
        auto model = loadObjectModel(*modelPath);
        if (!model) return engine::makeError("--model {}", model.error().message);
        mObjects.models.push_back(std::move(*model));
    }
    if (!mOptions.savePath.empty()) {
        mSavePath = mOptions.savePath;
    } else if (mStore->isSave(mWorldPath)) {
        mSavePath = mWorldPath;
    } else {
        mSavePath = defaultSavePath(mScene.name);
    }
    mStoreStatus = readStoreStatus(storePathFor(mSavePath));
    if (!mOptions.editLogPath.empty()) {
        mEditLog.open(mOptions.editLogPath);
        if (!mEditLog)
            return engine::makeError("{}: cannot write the edit log", mOptions.editLogPath);
        mEditLog << "# vox play edit log: world " << mWorldPath.string() << "\n";
    }
    if (!mOptions.frameLogPath.empty()) {
        mFrameLog.open(mOptions.frameLogPath);
        if (!mFrameLog)
            return engine::makeError("{}: cannot write the frame log", mOptions.frameLogPath);
        // wall: the whole loop iteration (input, HUD, edits, render + present, script actions);
        // render_call: Renderer::render alone; gpu: its passes' GPU time, present included.
        mFrameLog
            << "frame,wall_ms,render_call_ms,gpu_ms,present_gpu_ms,render_width,render_height,"
               "stream_regions,stream_in,stream_in_ms,stream_out,stream_out_ms\n";
    }
    if (!mOptions.walkLogPath.empty()) {
        if (engine::Status s = mWalkLogFile.open(mOptions.walkLogPath); !s) return s;
        mWalkLog = &mWalkLogFile.stream();
        *mWalkLog << WalkController::logHeader() << "\n";
    }

    WindowOptions windowOptions;
    windowOptions.size = mOptions.windowSize;
    windowOptions.title = title();
    auto window = Window::create(windowOptions);
    if (!window)
        return engine::Error{noDisplayMessage(window.error().message, mOptions.captureCommand)};
    mWindow = std::move(*window);

    engine::gpu::ContextOptions ctxOptions;
#ifndef NDEBUG
    ctxOptions.validation = true;
#endif
    ctxOptions.window = mWindow->handle();
    auto ctx = engine::gpu::Context::create(ctxOptions);
    if (!ctx) return ctx.error();
    mCtx = std::move(*ctx);
    mImGui = std::make_unique<ImGuiPlatform>();
    mPresenter = std::make_unique<engine::gpu::Presenter>(*mCtx, mWindow->framebufferSize(), true);
    mRenderer = std::make_unique<engine::render::Renderer>(*mCtx);
    mHud.visible = mOptions.hud;
    auto lighting =
        engine::scene::lightingFor(&mScene, mOptions.lighting, engine::scene::playDefaults());
    if (!lighting) return lighting.error();
    mLighting = *lighting;

    const auto& dev = mCtx->info();
    glm::ivec3 size = mScene.grid.sizeInVoxels();
    std::printf("vox play: %s (%d x %d x %d voxels, %u bricks) on %s%s; saves to %s\n",
                mScene.name.c_str(), size.x, size.y, size.z, mScene.grid.liveBricks(),
                dev.name.c_str(), mCtx->validationEnabled() ? " with validation" : "",
                mSavePath.string().c_str());
    if (mScript)
        std::printf("vox play: replaying %s (%zu steps, fixed %.4f s per frame)\n",
                    mOptions.scriptPath.c_str(), mScript->steps().size(), double(kScriptStep));
    std::fflush(stdout);
    // Live play starts looking around; a script's mouse is logical (never grabs a real one).
    setMouseLook(true);
    if (mStreaming) {
        const world::ResidencySettings& r = mStreaming->settings();
        std::printf(
            "vox play: streaming regions within %.0f voxels from %s, budget %.0f MiB, at "
            "most %zu region(s) and %zu bricks into the grid per frame; autosave off\n",
            double(r.radiusVoxels),
            mStreamStore.empty() ? "the terrain generator" : mStreamStore.string().c_str(),
            double(r.budgetBytes) / (1 << 20), mStreaming->regionsPerFrame(),
            mStreaming->bricksPerFrame());
        std::fflush(stdout);
    }
    if (mOptions.walk) message(mWalk.toggle(mScene, mCamera));
    return {};
}

// The grid follows the camera's regions; edited regions stay until their save commits.
void Sandbox::updateStreaming() {
    if (!mStreaming) return;
    if (mPinnedVersion != mWorldVersion || mPinnedEpoch != mCommittedEpoch) {
        std::vector<world::RegionKey> pinned = mScene.grid.regionsEditedAfter(mCommittedEpoch);
        std::vector<world::RegionKey> undo = mUndo.regions();
        pinned.insert(pinned.end(), undo.begin(), undo.end());
        mStreaming->pin(pinned);
        mPinnedVersion = mWorldVersion;
        mPinnedEpoch = mCommittedEpoch;
    }
    mStreamReport = mStreaming->update(mCamera.position(), mScene.grid);
    mPeakStreamRegions = std::max(mPeakStreamRegions, mStreaming->regionsInGrid());
    mPeakStreamBytes = std::max(mPeakStreamBytes, mStreaming->bytes());
    for (const std::string& e : mStreamReport.errors) message(e + " (seen as empty)");
}

void Sandbox::setMouseLook(bool on) {
    mMouseLook = on;
    if (!mScript) mWindow->setCursorCaptured(on);
    mInput.resetCursorTracking();
    if (!on) mTools.cancelDrag();
}

int Sandbox::run() {
    engine::Status s = init();
    if (!s) {
        const std::string& m = s.error().message;
        std::fprintf(stderr, "%s%s\n", m.rfind("vox play:", 0) == 0 ? "" : "vox play: ", m.c_str());
        return 1;
    }
    mLastFrameStart = std::chrono::steady_clock::now();
    while (!mQuit) frame();
    int exitCode = 0;
    if (mStreaming) {
        // The memory streaming held at its peak: the pools never shrink, so their capacity is it.
        const world::GridMemory cpu = mScene.grid.memory();
        const engine::render::GpuWorldMemory gpu = mRenderer->gpuWorld().memory();
        std::printf(
            "vox play: streaming: at most %zu region(s) in the grid, %.1f MiB counted against the "
            "budget; CPU grid: top grid %.1f MiB, brick pool %.1f MiB (%u bricks); GPU: top grid "
            "%.1f MiB, brick pages %.1f MiB\n",
            mPeakStreamRegions, double(mPeakStreamBytes) / (1 << 20),
            double(cpu.topGridBytes + cpu.superGridBytes + cpu.bookkeepingBytes) / (1 << 20),
            double(cpu.brickPoolBytes) / (1 << 20), mScene.grid.brickCapacity(),
            double(gpu.topGridBytes) / (1 << 20), double(gpu.brickPageBytes) / (1 << 20));
        std::fflush(stdout);
    }
    // Saves still being written finish before the process ends, and say how they went.
    mSaver.waitIdle();
    if (!pollSaves()) exitCode = 1;
    if (mWalkLog) {
        if (engine::Status c = mWalkLogFile.commit(); !c) {
            std::fprintf(stderr, "vox play: %s\n", c.error().message.c_str());
            exitCode = 1;
        }
    }
    if (mFrameLog.is_open() && !mFrameLog.flush()) {
        std::fprintf(stderr, "vox play: %s: cannot write the frame log (disk full?)\n",
                     mOptions.frameLogPath.c_str());
        exitCode = 1;
    }
    if (mEditLog.is_open() && !mEditLog.flush()) {
        std::fprintf(stderr, "vox play: %s: cannot write the edit log (disk full?)\n",
                     mOptions.editLogPath.c_str());
        exitCode = 1;
    }
    if (mCtx && mCtx->validationErrors() > 0) {
        std::fprintf(stderr, "vox play: %u Vulkan validation error(s)\n", mCtx->validationErrors());
        return 1;
    }
    return exitCode;
}

void Sandbox::frame() {
    const auto start = std::chrono::steady_clock::now();
    const float dt = advanceClock(start);
    pollInput();

    glm::uvec2 framebuffer = mWindow->framebufferSize();
    glm::uvec2 windowSize = mWindow->windowSize();
    glm::vec2 cursorScale = windowSize.x > 0 && windowSize.y > 0
                                ? glm::vec2(framebuffer) / glm::vec2(windowSize)
                                : glm::vec2(1.0f);
    mImGui->newFrame(mInput, framebuffer, cursorScale, dt, !mMouseLook);
    ImGui::NewFrame();

    handleInput(dt);
    updateStreaming();

    if (mTime - mMessageTime > kMessageSeconds) mMessage.clear();
    HudControls controls{mTools,     mScene.palette, mScene.sky, mRenderScale,
                         mAutoScale, mExposure,      mLighting};
    float scaleBefore = mRenderScale;
    HudActions actions = mHud.draw(hudStats(), controls, mQuitPrompt);
    if (mRenderScale != scaleBefore) mAutoScale = false;  // moved by hand: the hand wins
    mRenderScale = std::clamp(mRenderScale, kMinRenderScale, 1.0f);
    ImGui::Render();
    applyHudActions(actions);
    requestScriptCaptures();

    const RenderedFrame rendered = renderFrame(framebuffer);
    afterFrame(rendered.result, rendered.presented);
    const double wallMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (mAutoScale && rendered.presented) adjustRenderScale(wallMs, framebuffer);
    if (mFrameLog.is_open() && rendered.presented) {
        // stream_*: regions in the grid, and those written in and out this frame (streaming).
        // Flushed every row: a write error sticks in the stream's state and is reported at exit.
        mFrameLog << fmt::format(
            "{},{:.3f},{:.3f},{:.3f},{:.3f},{},{},{},{},{:.3f},{},{:.3f}\n", mFrame, wallMs,
            rendered.renderCallMs, rendered.result.totalMs(), rendered.result.passMsOf("present"),
            rendered.size.x, rendered.size.y, mStreaming ? mStreaming->regionsInGrid() : 0,
            mStreamReport.arrived, mStreamReport.inMs, mStreamReport.left, mStreamReport.outMs);
        mFrameLog.flush();
    }
    if (mWalkLog) *mWalkLog << mWalk.logRow(mFrame, mTime) << "\n";
    ++mFrame;
    if (mOptions.maxFrames && mFrame >= mOptions.maxFrames) {
        if (!mQuit) message(fmt::format("stopping after {} frames (--frames)", mOptions.maxFrames));
        mQuit = true;
    }
}

// This frame's time step: the script's fixed step, or the wall clock's (at most 0.1 s).
float Sandbox::advanceClock(std::chrono::steady_clock::time_point start) {
    float dt;
    if (mScript) {
        dt = kScriptStep;
    } else {
        dt = std::min(0.1f, std::chrono::duration<float>(start - mLastFrameStart).count());
    }
    mCpuFrameMs = std::chrono::duration<double, std::milli>(start - mLastFrameStart).count();
    mLastFrameStart = start;
    mTime += dt;
    return dt;
}

// Input: a script replaces live input entirely, except the close button.
void Sandbox::pollInput() {
    std::vector<InputEvent> live = mWindow->pollEvents();
    mInput.beginFrame();
    if (mScript) {
        for (const InputEvent& e : live) {
            if (e.type == InputEventType::Close) mInput.apply(e);
        }
        for (const InputEvent& e : mScript->eventsFor(mFrame)) mInput.apply(e);
    } else {
        for (const InputEvent& e : live) mInput.apply(e);
    }
}

// The HUD's buttons: undo, redo, save, and the quit prompt's answers.
void Sandbox::applyHudActions(const HudActions& actions) {
    if (actions.undo) undo();
    if (actions.redo) redo();
    if (actions.save) {
        if (engine::Status st = save(mSavePath, false); !st)
            message("save failed: " + st.error().message);
    }
    if (actions.quitSave || actions.quitDiscard || actions.quitCancel) {
        mQuitPrompt = false;
        if (actions.quitSave) {
            if (engine::Status st = save(mSavePath, false, /*wait=*/true); !st) {
                message("save failed: " + st.error().message);
            } else {
                mQuit = true;
            }
        }
        if (actions.quitDiscard) {
            message("quit without saving");
            mQuit = true;
        }
    }
}

// Script captures of the presented window must be requested before the frame is drawn.
void Sandbox::requestScriptCaptures() {
    if (!mScript) return;
    for (const ScriptAction& a : mScript->actionsFor(mFrame)) {
        if (a.kind == ScriptAction::Kind::Capture) {
            mCaptureRequested = true;
            mPendingCapturePath = a.path;
        }
    }
}

// Renders and presents the frame, unless the window is minimised (then it waits a little).
Sandbox::RenderedFrame Sandbox::renderFrame(glm::uvec2 framebuffer) {
    RenderedFrame out;
    if (!mPresenter->beginFrame(framebuffer)) {
        std::this_thread::sleep_for(std::chrono::milliseconds(16));  // minimised: do not spin
        return out;
    }
    engine::render::FrameSettings settings;
    glm::uvec2 size = renderSize(framebuffer);
    settings.width = size.x;
    settings.height = size.y;
    // A reconstructing display (--display upsampled or denoised) resolves to the window's size.
    settings.displayWidth = framebuffer.x;
    settings.displayHeight = framebuffer.y;
    settings.exposure = mExposure;
    settings.timeSeconds =
        mTime;  // dynamic objects: the script clock when scripted, else wall clock
    mPresenter->setOverlay(ImGui::GetDrawData());
    if (mCaptureRequested) mPresenter->captureThisFrame();
    const auto renderStart = std::chrono::steady_clock::now();
    out.result = mRenderer->render(mScene, mCamera.preset(), settings, mLighting, mPresenter.get());
    out.renderCallMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - renderStart)
            .count();
    out.size = size;
    out.presented = true;
    mLastFrame = out.result;
    return out;
}

// Auto scale: the whole frame's wall time steers it (host work and the window-size passes
// included: that is what the player waits for); the display stays the window's size.
void Sandbox::adjustRenderScale(double frameMs, glm::uvec2 framebuffer) {
    float next = mScaleController.update(mRenderScale, frameMs);
    if (next == mRenderScale) return;
    glm::uvec2 from = renderSize(framebuffer);
    mRenderScale = next;
    glm::uvec2 to = renderSize(framebuffer);
    message(fmt::format(
        "render {}x{} -> {}x{}: frames took {:.0f} ms (median, {:.0f} ms of it fixed), aiming at "
        "{:.0f} ms (auto scale)",
        from.x, from.y, to.x, to.y, mScaleController.lastMedianMs(), mScaleController.fixedMs(),
        mScaleController.targetMs()));
}

void Sandbox::handleInput(float dt) {
    if (mInput.closeRequested()) requestQuit();
    if (mQuitPrompt) {
        handleQuitPrompt();
        return;
    }
    bool hudMouse = !mMouseLook && mImGui->wantsMouse();

    if (mInput.pressed(GLFW_KEY_ESCAPE)) {
        if (mTools.dragging()) {
            mTools.cancelDrag();
        } else if (mMouseLook) {
            setMouseLook(false);
        } else {
            requestQuit();
            return;
        }
    }
    // A click on the world (not on the HUD) takes the mouse back; it does not edit.
    bool clickCaptured = false;
    if (!mMouseLook && !hudMouse && mInput.buttonPressed(GLFW_MOUSE_BUTTON_LEFT)) {
        setMouseLook(true);
        clickCaptured = true;
    }

    if (!mInput.ctrl() && mInput.pressed(GLFW_KEY_F)) message(mWalk.toggle(mScene, mCamera));
    if (mWalk.active()) {
        // Unloaded ground is air: the player waits until the regions around it are in.
        const world::PlayerBox b = mWalk.body().box();
        const glm::ivec3 margin(16);
        mStreamWait = streamedBoxMissing(
            {glm::ivec3(glm::floor(b.min)) - margin, glm::ivec3(glm::ceil(b.max)) + margin});
        if (mStreamWait) {
        } else if (std::string m = mWalk.update(mInput, dt, mTime, mMouseLook, mScene, mCamera);
                   !m.empty()) {
            message(m);
        }
    } else {
        mStreamWait = false;
        mCamera.update(mInput, dt, mMouseLook);
    }
    mTarget = pick(mScene.grid, mCamera.position(), mCamera.forward());

    if (mMouseLook && !clickCaptured && !mObjects.active) handleEditClicks();

    if (mInput.ctrl()) {
        if (mInput.pressed(GLFW_KEY_Z)) mInput.shift() ? redo() : undo();
        if (mInput.pressed(GLFW_KEY_Y)) redo();
        if (mInput.pressed(GLFW_KEY_S)) {
            if (engine::Status st = save(mSavePath, false); !st)
                message("save failed: " + st.error().message);
        }
        return;  // Ctrl+key is a command, never also a tool key
    }
    handleToolKeys(hudMouse, clickCaptured);
}

// The mouse buttons on the world: the tool (left), removing (right), the eyedropper (middle, I).
void Sandbox::handleEditClicks() {
    // A press or release that edits nothing says why (the sky, a ray that is not finite).
    auto use = [&](bool pressed) {
        bool wasDragging = mTools.dragging();
        std::optional<EditOp> op = pressed ? mTools.press(mTarget) : mTools.release(mTarget);
        if (op)
            applyEdit(*op);
        else if (pressed && !mTarget.hit)
            message(
                fmt::format("{}: nothing edited: {}", toolName(mTools.tool), missReason(mTarget)));
        else if (!pressed && wasDragging)
            message(fmt::format("box released over no surface: nothing edited: {}",
                                missReason(mTarget)));
    };
    if (mInput.buttonPressed(GLFW_MOUSE_BUTTON_LEFT)) use(true);
    if (mInput.buttonReleased(GLFW_MOUSE_BUTTON_LEFT)) use(false);
    // Right button: remove with the current brush, whatever the tool.
    if (mInput.buttonPressed(GLFW_MOUSE_BUTTON_RIGHT) ||
        mInput.buttonReleased(GLFW_MOUSE_BUTTON_RIGHT)) {
        Tool saved = mTools.tool;
        mTools.tool = Tool::Remove;
        use(mInput.buttonPressed(GLFW_MOUSE_BUTTON_RIGHT));
        mTools.tool = saved;
    }
    if (mInput.buttonPressed(GLFW_MOUSE_BUTTON_MIDDLE) || mInput.pressed(GLFW_KEY_I)) {
        if (mTools.eyedrop(mTarget)) message("eyedropper: " + mScene.palette[mTools.material].name);
    }
}

// Keys without Ctrl: tools, brush, material, render scale, camera presets, HUD, screenshots.
void Sandbox::handleToolKeys(bool hudMouse, bool clickCaptured) {
    if (mInput.pressed(GLFW_KEY_1)) mTools.tool = Tool::Place;
    if (mInput.pressed(GLFW_KEY_2)) mTools.tool = Tool::Remove;
    if (mInput.pressed(GLFW_KEY_3)) mTools.tool = Tool::Paint;
    if (mInput.pressed(GLFW_KEY_1) || mInput.pressed(GLFW_KEY_2) || mInput.pressed(GLFW_KEY_3))
        mObjects.active = false;
    if (mInput.pressed(GLFW_KEY_4)) {
        mObjects.active = true;
        mTools.cancelDrag();
        message(mObjects.status(mScene));
    }
    if (mObjects.active) handleObjects(mMouseLook && !clickCaptured);
    if (mInput.pressed(GLFW_KEY_B)) {
        mTools.cancelDrag();
        mTools.brush = static_cast<Brush>((static_cast<int>(mTools.brush) + 1) % 3);
        message(fmt::format("brush: {}", brushName(mTools.brush)));
    }
    if (mInput.pressed(GLFW_KEY_MINUS)) mTools.radius = std::max(0.5f, mTools.radius - 0.5f);
    if (mInput.pressed(GLFW_KEY_EQUAL)) mTools.radius = std::min(32.0f, mTools.radius + 0.5f);
    int materialStep =
        (mInput.pressed(GLFW_KEY_PERIOD) ? 1 : 0) - (mInput.pressed(GLFW_KEY_COMMA) ? 1 : 0);
    if (!hudMouse && mInput.scroll() != 0.0f) materialStep += mInput.scroll() > 0.0f ? -1 : 1;
    int materials = static_cast<int>(mScene.palette.size()) - 1;
    if (materialStep != 0 && materials > 0) {
        int m = (static_cast<int>(mTools.material) - 1 + materialStep) % materials;
        mTools.material = static_cast<world::MaterialId>((m + materials) % materials + 1);
    }
    if (mInput.pressed(GLFW_KEY_PAGE_UP) || mInput.pressed(GLFW_KEY_PAGE_DOWN)) {
        mAutoScale = false;
        mRenderScale = mInput.pressed(GLFW_KEY_PAGE_UP)
                           ? std::min(1.0f, mRenderScale * 1.25f)
                           : std::max(kMinRenderScale, mRenderScale / 1.25f);
        message(
            fmt::format("render scale {:.3f} (auto off; the HUD turns it back on)", mRenderScale));
    }
    if (mInput.pressed(GLFW_KEY_C) && !mScene.cameras.empty()) {
        mCameraIndex = (mCameraIndex + 1) % mScene.cameras.size();
        mCamera.setFromPreset(mScene.cameras[mCameraIndex]);
        if (mWalk.active()) mWalk.placeAtCamera(mScene, mCamera);
        message("camera: " + mScene.cameras[mCameraIndex].name);
    }
    if (mInput.pressed(GLFW_KEY_TAB)) mHud.visible = !mHud.visible;
    if (mInput.pressed(GLFW_KEY_F1)) mHud.showKeys = !mHud.showKeys;
    if (mInput.pressed(GLFW_KEY_F12)) {
        // Named after the world, made safe: a scene's `name` is any text ("../x", "/").
        fs::path path =
            fs::path("screenshots") / fmt::format("{}-{}.png", worldFileStem(mScene.name), mFrame);
        if (mInput.shift()) {
            mPendingRenderPath = path;
        } else {
            mCaptureRequested = true;
            mPendingCapturePath = path;
        }
    }
}

void Sandbox::handleQuitPrompt() {
    if (mInput.pressed(GLFW_KEY_Y) || mInput.pressed(GLFW_KEY_ENTER)) {
        mQuitPrompt = false;
        if (engine::Status st = save(mSavePath, false, /*wait=*/true); !st) {
            message("save failed: " + st.error().message);
        } else {
            mQuit = true;
        }
    } else if (mInput.pressed(GLFW_KEY_N)) {
        mQuitPrompt = false;
        message("quit without saving");
        mQuit = true;
    } else if (mInput.pressed(GLFW_KEY_ESCAPE)) {
        mQuitPrompt = false;
        message("quit cancelled");
    }
}

void Sandbox::requestQuit() {
    if (!unsaved()) {
        mQuit = true;
        return;
    }
    if (!mQuitPrompt) {
        mQuitPrompt = true;
        setMouseLook(false);
        message(fmt::format(
            "unsaved changes: Y saves and quits, N quits without saving, Esc cancels ({})",
            mSavePath.string()));
    }
}

void Sandbox::applyEdit(const EditOp& op) {
    if (op.tool != Tool::Remove &&
        (op.material == world::kEmpty || op.material >= mScene.palette.size())) {
        message(
            fmt::format("{}: refused: the world has no materials (a --model object brings its own; "
                        "then , and . "
                        "choose one)",
                        toolName(op.tool)));
        return;
    }
    if (streamedBoxMissing(op.region())) {
        message(op.describe(mScene.palette) +
                ": refused: it reaches a region not loaded yet (streaming: come closer)");
        return;
    }
    if (std::string why = mWalk.refusal(op, mScene.grid); !why.empty()) {
        message(op.describe(mScene.palette) + ": refused: " + why);
        return;
    }
    EditRecord rec = mUndo.record(mScene.grid, op.region(), op.describe(mScene.palette),
                                  [&](world::BrickGrid& grid) { game::applyEdit(grid, op); });
    if (rec.changedCells == 0) {
        message(op.describe(mScene.palette) +
                ": nothing changed: " + unchangedReason(mScene.grid, op, mScene.palette));
        return;
    }
    ++mWorldVersion;
    ++mFrameEdits;
    mFrameChangedCells += rec.changedCells;
    if (mEditLog) {
        glm::vec3 o = mCamera.position(), d = mCamera.forward();
        mEditLog << fmt::format(
            "edit {} {} {} ray {} {} {} {} {} {} box {} {} {} {} {} {} sphere {} {} {} {} material "
            "{} cells {}\n",
            mFrame, toolName(op.tool), brushName(op.brush), o.x, o.y, o.z, d.x, d.y, d.z,
            op.box.min.x, op.box.min.y, op.box.min.z, op.box.max.x, op.box.max.y, op.box.max.z,
            op.center.x, op.center.y, op.center.z, op.radius, op.material, rec.changedCells);
        mEditLog.flush();
    }
    message(fmt::format("{} ({} cell{}){}", op.describe(mScene.palette), rec.changedCells,
                        rec.changedCells == 1 ? "" : "s",
                        rec.undoable ? "" : " - too large to undo within the budget"));
}

void Sandbox::handleObjects(bool clicks) {
    ObjectResult r = mObjects.handle(mInput, clicks, mTarget, mCamera.position(), mCamera.forward(),
                                     mScene, mUndo, mTime);
    if (r.changed) ++mWorldVersion;
    if (!r.message.empty()) message(r.message);
}

void Sandbox::undo() {
    if (mObjects.finishDrag(mScene, mUndo).changed) ++mWorldVersion;
    std::string label = mUndo.undo(mScene.grid, mScene.objects);
    mObjects.objectsChanged(mScene);
    refreshObjects(mScene, mTime);
    if (label.empty()) {
        message("nothing to undo");
        return;
    }
    ++mWorldVersion;
    if (mEditLog) mEditLog << fmt::format("undo {}\n", mFrame) << std::flush;
    message("undo: " + label);
}

void Sandbox::redo() {
    if (mObjects.finishDrag(mScene, mUndo).changed) ++mWorldVersion;
    std::string label = mUndo.redo(mScene.grid, mScene.objects);
    mObjects.objectsChanged(mScene);
    refreshObjects(mScene, mTime);
    if (label.empty()) {
        message("nothing to redo");
        return;
    }
    ++mWorldVersion;
    if (mEditLog) mEditLog << fmt::format("redo {}\n", mFrame) << std::flush;
    message("redo: " + label);
}

engine::Status Sandbox::save(const fs::path& path, bool autosave, bool wait) {
    if (mStreaming && mStreamStore.empty())
        return engine::makeError(
            "a generated world streamed region by region cannot be saved yet: make it a store "
            "first (vox import {} -o W.db) and play that",
            mWorldPath.string());
    if (mStreaming &&
        fs::weakly_canonical(storePathFor(path)) != fs::weakly_canonical(mStreamStore))
        return engine::makeError("a streamed world saves only into the store it streams from ({})",
                                 mStreamStore.string());
    const std::uint32_t epoch = mScene.grid.editEpoch();  // the save holds what is stamped up to it
    // The current view becomes the first camera preset, so reopening the save resumes here.
    std::vector<world::CameraPreset> presets = mScene.cameras;
    world::CameraPreset view = mCamera.preset();
    view.name = kSavedViewName;
    // A camera that is not finite would be written and refused on loading: refuse it here.
    if (engine::Status ok = world::checkCamera(view); !ok) return ok;
    std::erase_if(mScene.cameras,
                  [](const world::CameraPreset& c) { return c.name == kSavedViewName; });
    mScene.cameras.insert(mScene.cameras.begin(), view);
    // In the frame: a copy of the regions edited since the last save to this file; the worker
    // writes them.
    auto regions = mSaver.request(mScene, path, autosave, mWorldVersion);
    mScene.cameras = std::move(presets);
    if (!regions) return regions.error();
    mAutosave.written(mTime, mWorldVersion);
    if (!autosave) mPendingSaveVersion = mWorldVersion;
    if (!autosave && mStreaming) mSaveEpochs[mWorldVersion] = epoch;
    if (mEditLog)
        mEditLog << fmt::format("{} {} {}\n", autosave ? "autosave" : "save", mFrame, path.string())
                 << std::flush;
    if (wait) {
        mSaver.waitIdle();
        return pollSaves(/*quiet=*/true);
    }
    return {};
}

engine::Status Sandbox::pollSaves(bool quiet) {
    engine::Status last;
    for (BackgroundSaver::Done& d : mSaver.poll(mScene)) {
        if (!d.autosave && mPendingSaveVersion == d.worldVersion) mPendingSaveVersion.reset();
        if (!d.status) {
            if (!quiet || d.autosave)
                message(fmt::format("{} failed: {}", d.autosave ? "autosave" : "save",
                                    d.status.error().message));
            if (d.autosave) mAutosave.postpone(mTime);  // try again after another interval
            last = d.status;
            continue;
        }
        if (!d.autosave) {
            // Committed: the regions it held may leave memory now.
            if (auto e = mSaveEpochs.find(d.worldVersion); e != mSaveEpochs.end())
                mCommittedEpoch = std::max(mCommittedEpoch, e->second);
            mSaveEpochs.erase(mSaveEpochs.begin(), mSaveEpochs.upper_bound(d.worldVersion));
            mSavedVersion = d.worldVersion;
            mStoreStatus = {true, d.report.regionRows, d.report.fileBytes};
        }
        message(fmt::format(
            "{} {} ({}{} region(s), {:.1f} MiB stored; {:.1f} ms in the frame, {:.0f} ms on the "
            "worker: encode {:.0f}, commit {:.0f})",
            d.autosave ? "autosaved to" : "saved", d.savePath.string(),
            d.whole ? "whole world: " : "", d.report.regionsWritten + d.report.regionsErased,
            double(d.report.storedBytes) / (1 << 20), d.frameMs, d.workerMs, d.report.encodeMs,
            d.report.commitMs));
    }
    return last;
}

void Sandbox::logView(const char* what, const fs::path& path) {
    if (!mEditLog) return;
    world::CameraPreset c = mCamera.preset();
    glm::uvec2 size = renderSize(mWindow->framebufferSize());
    mEditLog << fmt::format(
                    "{} {} {} view {} {} {} {} {} {} fov {} size {} {} frame {} exposure {} "
                    "lighting {}\n",
                    what, mFrame, path.string(), c.position.x, c.position.y, c.position.z,
                    c.target.x, c.target.y, c.target.z, c.fovYDegrees, size.x, size.y, mFrame,
                    mExposure, engine::lighting::methodName(mLighting.method))
             << std::flush;
}

void Sandbox::writeRenderImage(const fs::path& path) {
    engine::render::FrameImages images = mRenderer->readback();
    std::error_code ec;
    if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
    engine::Status s =
        engine::io::writePng(path, images.displayWidth, images.displayHeight, images.rgba8);
    if (!s) {
        message("screenshot failed: " + s.error().message);
        return;
    }
    logView("screenshot", path);
    message(fmt::format("screenshot {} ({}x{}, rendered image)", path.string(), images.displayWidth,
                        images.displayHeight));
}

void Sandbox::writeWindowCapture(const fs::path& path) {
    const engine::gpu::WindowCapture& cap = mPresenter->capture();
    if (cap.rgba8.empty()) {
        message("window capture failed: no frame was presented");
        return;
    }
    std::error_code ec;
    if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
    engine::Status s = engine::io::writePng(path, cap.width, cap.height, cap.rgba8);
    if (!s) {
        message("screenshot failed: " + s.error().message);
        return;
    }
    logView("capture", path);
    message(fmt::format("screenshot {} ({}x{}, window with HUD)", path.string(), cap.width,
                        cap.height));
}

void Sandbox::afterFrame(const engine::render::FrameResult& result, bool presented) {
    if (mFrameEdits > 0 && presented) {
        // The latency contract: this frame showed the edits and uploaded only what they touched.
        std::printf(
            "frame %llu: presented %zu edit(s) changing %zu cell(s); uploaded %u brick(s), %u "
            "cell(s)%s\n",
            static_cast<unsigned long long>(mFrame), mFrameEdits, mFrameChangedCells,
            result.upload.bricks, result.upload.cells, result.upload.full ? " (full upload)" : "");
        std::fflush(stdout);
        mFrameEdits = 0;
        mFrameChangedCells = 0;
    }
    if (presented && mCaptureRequested) {
        mCaptureRequested = false;
        writeWindowCapture(mPendingCapturePath);
    }
    if (presented && !mPendingRenderPath.empty()) {
        writeRenderImage(mPendingRenderPath);
        mPendingRenderPath.clear();
    }
    if (mScript) runScriptActions();
    (void)pollSaves();  // reported by message()
    if (!mStreaming && mAutosave.due(mTime, mWorldVersion)) {
        engine::Status s = save(autosavePath(mSavePath), true);
        if (!s) {
            message("autosave failed: " + s.error().message);
            mAutosave.postpone(mTime);  // try again after another interval
        }
    }
    if (std::string t = title(); t != mTitle) {
        mWindow->setTitle(t);
        mTitle = std::move(t);
    }
}

void Sandbox::runScriptActions() {
    for (const ScriptAction& a : mScript->actionsFor(mFrame)) {
        switch (a.kind) {
            case ScriptAction::Kind::Screenshot:
                writeRenderImage(a.path);
                break;
            case ScriptAction::Kind::Capture:
                break;  // written with the frame above
            case ScriptAction::Kind::Resize:
                mWindow->resize(a.size);
                message(fmt::format("window resized to {}x{}", a.size.x, a.size.y));
                break;
            case ScriptAction::Kind::Quit:
                requestQuit();
                break;
        }
    }
    // A script that ends without quitting stops one frame after its last step.
    if (!mQuit && mFrame > mScript->lastFrame()) {
        message(unsaved() ? "script ended with unsaved changes; quitting without saving"
                          : "script ended");
        mQuit = true;
    }
}

HudStats Sandbox::hudStats() {
    HudStats s;
    s.cpuFrameMs = mCpuFrameMs;
    s.passMs = mLastFrame.passMs;
    glm::uvec2 fb = mWindow->framebufferSize();
    s.renderSize = renderSize(fb);
    s.windowSize = fb;
    s.frame = mFrame;
    s.liveBricks = mScene.grid.liveBricks();
    s.emitters = mRenderer->emitters().aliveCount();
    s.regirSampling = mLastFrame.regirSampling;
    s.cpuMemory = mScene.grid.memory();
    s.gpuMemory = mRenderer->gpuWorld().memory();
    s.cacheUsed = mLastFrame.cacheUsed;
    s.cache = mLastFrame.cache;
    s.skyUsed = mLastFrame.skyUsed;
    s.accumulatedFrames = mLastFrame.accumulatedFrames;
    s.sky = mLastFrame.sky;
    s.undo = mUndo.stats();
    s.worldName = mScene.name;
    s.savePath = mSavePath.string();
    s.store = describeStore(storePathFor(mSavePath), mStoreStatus);
    if (mStreaming)
        s.streaming =
            fmt::format("streaming: {} region(s) in memory, {:.0f} of {:.0f} MiB, {} loading{}",
                        mStreaming->regionsInGrid(), double(mStreaming->bytes()) / (1 << 20),
                        double(mStreaming->settings().budgetBytes) / (1 << 20),
                        mStreamReport.pending + mStreamReport.waiting,
                        mStreamWait ? " - loading the ground around the player: waiting" : "");
    s.unsaved = unsaved();
    s.mouseLook = mMouseLook;
    s.target = mTarget;
    s.preview = mObjects.active ? std::nullopt : mTools.preview(mTarget);
    if (mObjects.active) s.objectTool = mObjects.status(mScene);
    engine::render::FrameSettings settings;
    settings.width = s.renderSize.x;
    settings.height = s.renderSize.y;
    s.view = engine::render::makeFrameParams(mCamera.preset(), mScene.sky, settings);
    s.message = mMessage;
    s.movement = mWalk.hudText();
    return s;
}

}  // namespace

int runPlay(const PlayOptions& options) {
    if (std::string why = displayProblem(); !why.empty()) {
        std::fprintf(stderr, "%s\n", noDisplayMessage(why, options.captureCommand).c_str());
        return 1;
    }
    Sandbox sandbox(options);
    return sandbox.run();
}

}  // namespace game
