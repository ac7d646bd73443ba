#include "scene_tree.h"

#include <QHeaderView>

#include "json_pointer.h"
#include "scene_document.h"

namespace lenslab::gui {

namespace {

constexpr int kPointerRole = Qt::UserRole;
// Unnamed objects of one type in a row, from this many on, are folded into one row.
constexpr size_t kFoldedRun = 4;

QTreeWidgetItem* add_item(QTreeWidgetItem* parent, const QString& text, const QString& pointer) {
    auto* item = new QTreeWidgetItem(parent, {text});
    item->setData(0, kPointerRole, pointer);
    return item;
}

}  // namespace

SceneTree::SceneTree(SceneDocument* document, QWidget* parent)
    : QTreeWidget(parent), m_document(document) {
    setHeaderHidden(true);
    setObjectName("scene_tree");
    connect(document, &SceneDocument::changed, this, &SceneTree::rebuild);
    connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        emit pointer_selected(item ? item->data(0, kPointerRole).toString() : QString());
    });
    rebuild();
}

QString SceneTree::selected_pointer() const {
    return currentItem() ? currentItem()->data(0, kPointerRole).toString() : QString();
}

void SceneTree::select_pointer(const QString& pointer) {
    for (QTreeWidgetItemIterator it(this); *it; ++it) {
        if ((*it)->data(0, kPointerRole).toString() == pointer) {
            // An object picked in the view may sit in a folded run.
            for (QTreeWidgetItem* p = (*it)->parent(); p; p = p->parent()) p->setExpanded(true);
            setCurrentItem(*it);
            return;
        }
    }
    setCurrentItem(nullptr);
}

void SceneTree::rebuild() {
    const QString keep = selected_pointer();
    const QSignalBlocker block(this);
    clear();
    const auto& j = m_document->json();
    if (j.contains("description") && j["description"].is_string())
        add_item(invisibleRootItem(), tr("About this scene"), "/description");
    add_item(invisibleRootItem(), tr("Camera"), "/camera");
    add_item(invisibleRootItem(), tr("Render settings"), "/render");
    if (j.contains("atmosphere")) add_item(invisibleRootItem(), tr("Atmosphere"), "/atmosphere");
    auto* materials = add_item(invisibleRootItem(), tr("Materials"), "");
    if (j.contains("materials")) {
        for (const auto& [name, value] : j["materials"].items()) {
            // Names are free text: "a/b" must be one token ("/materials/a~1b").
            add_item(materials, QString::fromStdString(name),
                     join_pointer("/materials", QString::fromStdString(name)));
        }
    }
    auto* objects = add_item(invisibleRootItem(), tr("Objects"), "");
    if (j.contains("objects")) {
        const auto& list = j["objects"];
        // A run of unnamed objects of one type (a floor of 128 triangles) is one row,
        // folded; its objects are its children.
        const auto unnamed_type = [&](size_t i) {
            return list[i].contains("name") ? std::string() : list[i].value("type", "?");
        };
        for (size_t i = 0; i < list.size();) {
            size_t end = i + 1;
            const std::string run_type = unnamed_type(i);
            while (!run_type.empty() && end < list.size() && unnamed_type(end) == run_type) ++end;
            QTreeWidgetItem* parent = objects;
            if (end - i >= kFoldedRun) {
                parent = add_item(objects,
                                  tr("%1 × %2 (objects[%3] to objects[%4])")
                                      .arg(end - i)
                                      .arg(QString::fromStdString(run_type))
                                      .arg(i)
                                      .arg(end - 1),
                                  "");
            }
            for (; i < end; ++i) {
                const auto& o = list[i];
                const QString type = QString::fromStdString(o.value("type", "?"));
                const QString name = o.contains("name")
                                         ? QString::fromStdString(o["name"].get<std::string>())
                                         : QString("objects[%1]").arg(i);
                add_item(parent, QString("%1 (%2)").arg(name, type),
                         join_pointer("/objects", qsizetype(i)));
            }
        }
    }
    auto* lights = add_item(invisibleRootItem(), tr("Lights"), "");
    if (j.contains("lights")) {
        for (size_t i = 0; i < j["lights"].size(); ++i) {
            add_item(lights,
                     QString("%1 light %2")
                         .arg(QString::fromStdString(j["lights"][i].value("type", "?")))
                         .arg(i),
                     join_pointer("/lights", qsizetype(i)));
        }
    }
    materials->setExpanded(true);
    objects->setExpanded(true);
    lights->setExpanded(true);
    select_pointer(keep);
}

}  // namespace lenslab::gui
