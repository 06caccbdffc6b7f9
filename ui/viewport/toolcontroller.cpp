#include "ui/viewport/toolcontroller.h"

#include <QKeyEvent>

#include "engine/util/error.h"
#include "ui/viewport/tools/branchtool.h"
#include "ui/viewport/tools/brushtool.h"
#include "ui/viewport/tools/erasetool.h"
#include "ui/viewport/tools/placetool.h"
#include "ui/viewport/tools/selecttool.h"

namespace sylva::ui {

namespace {
constexpr float kNudge = 0.1f; ///< metres per arrow key (Shift: 10×)
} // namespace

QString ToolController::name(Tool tool) {
    switch (tool) {
    case Tool::Select:
        return QStringLiteral("select");
    case Tool::Move:
        return QStringLiteral("move");
    case Tool::Place:
        return QStringLiteral("place");
    case Tool::Brush:
        return QStringLiteral("brush");
    case Tool::Erase:
        return QStringLiteral("erase");
    case Tool::Branch:
        return QStringLiteral("branch");
    }
    return {};
}

bool ToolController::fromName(const QString& text, Tool& tool) {
    for (Tool t : {Tool::Select, Tool::Move, Tool::Place, Tool::Brush, Tool::Erase, Tool::Branch})
        if (name(t) == text) {
            tool = t;
            return true;
        }
    return false;
}

ToolController::ToolController(doc::Document& document, Viewport& viewport,
                               std::function<const GenerationResult&()> result, QObject* parent)
    : QObject(parent), mContext(document, viewport, std::move(result)) {
    mContext.message = [this](const QString& text) { Q_EMIT message(text); };
    mContext.treeBranchClicked = [this](std::uint32_t id, const glm::vec3& local) {
        Q_EMIT treeBranchClicked(id, local);
    };
    mSelect = std::make_unique<SelectTool>(mContext);
    mMove = std::make_unique<MoveTool>(mContext, *mSelect);
    mPlace = std::make_unique<PlaceTool>(mContext);
    mBrush = std::make_unique<BrushTool>(mContext);
    mErase = std::make_unique<EraseTool>(mContext);
    mBranch = std::make_unique<BranchTool>(mContext);
    viewport.setTool(this);
    viewport.setOverlay([this] { return handleLines(); });
}

ToolController::~ToolController() = default;

SceneTool& ToolController::current() {
    switch (mTool) {
    case Tool::Select:
        return *mSelect;
    case Tool::Move:
        return *mMove;
    case Tool::Place:
        return *mPlace;
    case Tool::Brush:
        return *mBrush;
    case Tool::Erase:
        return *mErase;
    case Tool::Branch:
        return *mBranch;
    }
    return *mSelect;
}

void ToolController::setTool(Tool tool) {
    if (tool == mTool) return;
    // The selected branch belongs to the Branch tool: another tool selects its tree.
    if (mTool == Tool::Branch && mContext.document.selectedBranch())
        mContext.document.setSelectedBranch(std::nullopt);
    mTool = tool;
    mContext.viewport.setPreviewTrees({});
    mContext.viewport.update(); // the Move tool's handles come or go
    Q_EMIT toolChanged(tool);
}

void ToolController::setPlaceSpecies(const std::string& species) {
    mPlace->setSpecies(species);
}

std::string ToolController::placeSpecies() const {
    return mPlace->species();
}

void ToolController::setBrush(const Brush& brush) {
    requireRange("brush radius (m)", brush.radius, 0.5, 100);
    requireRange("brush density (trees per 100 m2)", brush.density, 0.01, 50);
    for (const auto& [name, weight] : brush.mix) {
        if (mContext.document.speciesIndex(name) < 0)
            throw InvalidInput("unknown species '" + name + "'");
        requireRange("species weight", weight, 0, 1e6);
    }
    mContext.brush = brush;
}

float ToolController::crownRadius(std::uint32_t species) const {
    return mContext.crownRadius(species);
}

void ToolController::stepSelection(int step) {
    mSelect->stepSelection(step);
}

std::optional<ToolController::Handles> ToolController::handles() const {
    if (mTool != Tool::Move) return std::nullopt;
    return mMove->handles();
}

ToolController::Handle ToolController::handleAt(const QPoint& pos) const {
    if (mTool != Tool::Move) return Handle::None;
    return mMove->handleAt(pos);
}

std::vector<OverlayLine> ToolController::handleLines() const {
    if (mTool == Tool::Branch) return mBranch->lines();
    if (mTool != Tool::Move) return {};
    return mMove->handleLines();
}

bool ToolController::press(QMouseEvent* event) {
    return current().press(event);
}

void ToolController::move(QMouseEvent* event) {
    current().move(event);
}

void ToolController::release(QMouseEvent* event) {
    current().release(event);
}

void ToolController::click(QMouseEvent* event) {
    current().click(event);
}

bool ToolController::key(QKeyEvent* event) {
    if (current().key(event)) return true;
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    switch (event->key()) {
    case Qt::Key_BracketLeft:
        stepSelection(-1);
        return true;
    case Qt::Key_BracketRight:
        stepSelection(+1);
        return true;
    case Qt::Key_Left:
        mMove->nudge(-(shift ? 10 : 1) * kNudge, 0);
        return true;
    case Qt::Key_Right:
        mMove->nudge((shift ? 10 : 1) * kNudge, 0);
        return true;
    case Qt::Key_Up:
        mMove->nudge(0, -(shift ? 10 : 1) * kNudge);
        return true;
    case Qt::Key_Down:
        mMove->nudge(0, (shift ? 10 : 1) * kNudge);
        return true;
    default:
        return false;
    }
}

} // namespace sylva::ui
