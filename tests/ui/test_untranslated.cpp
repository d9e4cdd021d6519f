// SPDX-License-Identifier: GPL-3.0-or-later
// No English left in the Czech window, no Czech in the English one. The window is opened in
// each language on the welcome scene, every step of every shipped lesson and Help › Controls;
// every text a student can see or open is collected (widgets' texts, tooltips, every menu's
// actions, tabs, tables, text browsers, plots' titles, axes, legends, marks) and paired by
// where it is (the path of object names from the window, and the property), the same in both
// languages because both windows are built by the same code in the same order. What counts as
// a text left in the other language is text_scan.h's (checked by test_text_scan).

#include "common/language.h"
#include "lesson_player/lesson_player.h"
#include "window/main_window.h"

#include "shipped_lessons.h"
#include "test_main.h"
#include "text_scan.h"

#include <qcustomplot.h>

#include <QAbstractButton>
#include <QAbstractItemModel>
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMap>
#include <QMenu>
#include <QPlainTextEdit>
#include <QSet>
#include <QSettings>
#include <QTabBar>
#include <QTableWidget>
#include <QTextEdit>
#include <QTimer>
#include <QtTest>

#include <algorithm>
#include <memory>

using namespace rigidlab;
using rigidlab::test::hasCzechLetter;
using rigidlab::test::invariant;
using rigidlab::test::pieces;
using rigidlab::test::withoutMnemonics;
using rigidlab::ui::MainWindow;

namespace {

/// Whether the Czech window must have no English left (on since the translation is complete;
/// off, the untranslated texts would only be listed with QWARN). The English check is always
/// on.
constexpr bool kRequireCompleteCzech = true;

/// Objects whose texts are the same in every language, by object name: each language's entry
/// in View › Language is in its own name, and Open recent lists file names.
const QSet<QString>& invariantObjects()
{
    static const QSet<QString> names{QStringLiteral("language-en"), QStringLiteral("language-cs"),
                                     QStringLiteral("recentMenu")};
    return names;
}

/// Texts at one place of the window (a scene or a lesson step): key -> the pieces there.
using Texts = QMap<QString, QStringList>;

/// The collected texts of one window at one place.
class Collector {
public:
    explicit Collector(Texts& out) : m_out(out) {}

    void add(const QString& key, const QString& text)
    {
        if (!text.isEmpty())
            m_out[key] << pieces(text);
    }

    /// One segment of an object's path: its object name, or its class, and its index among
    /// its parent's children of the same segment.
    static QString segment(const QObject* o)
    {
        const auto name = [](const QObject* x) {
            return x->objectName().isEmpty() ? QString::fromLatin1(x->metaObject()->className())
                                             : x->objectName();
        };
        const QString own = name(o);
        int index = 0;
        if (const QObject* parent = o->parent())
            for (const QObject* sibling : parent->children()) {
                if (sibling == o)
                    break;
                if (name(sibling) == own)
                    ++index;
            }
        return own + u'[' + QString::number(index) + u']';
    }

    /// The path of an object from the window (or from its top, for one outside it).
    static QString path(const QObject* o)
    {
        QStringList parts;
        for (; o; o = o->parent())
            parts.prepend(segment(o));
        return parts.join(u'/');
    }

    static bool insideInvariant(const QObject* o)
    {
        for (; o; o = o->parent())
            if (invariantObjects().contains(o->objectName()))
                return true;
        return false;
    }

    void widget(const QWidget* w)
    {
        const QString at = path(w);
        const auto key = [&at](const char* property) {
            return at + u'#' + QLatin1String(property);
        };
        add(key("toolTip"), w->toolTip());
        add(key("statusTip"), w->statusTip());
        add(key("whatsThis"), w->whatsThis());
        if (w->isWindow())
            add(key("windowTitle"), w->windowTitle());
        if (const auto* label = qobject_cast<const QLabel*>(w))
            add(key("text"), label->text());
        if (const auto* button = qobject_cast<const QAbstractButton*>(w))
            add(key("text"), button->text());
        if (const auto* edit = qobject_cast<const QLineEdit*>(w))
            add(key("placeholderText"), edit->placeholderText());
        if (const auto* box = qobject_cast<const QGroupBox*>(w))
            add(key("title"), box->title());
        if (const auto* dock = qobject_cast<const QDockWidget*>(w))
            add(key("windowTitle"), dock->windowTitle());
        if (const auto* tabs = qobject_cast<const QTabBar*>(w))
            for (int i = 0; i < tabs->count(); ++i) {
                add(key("tabText"), tabs->tabText(i));
                add(key("tabToolTip"), tabs->tabToolTip(i));
            }
        if (const auto* combo = qobject_cast<const QComboBox*>(w))
            for (int i = 0; i < combo->count(); ++i)
                add(key("itemText"), combo->itemText(i));
        if (const auto* text = qobject_cast<const QTextEdit*>(w))
            add(key("plainText"), text->toPlainText());
        if (const auto* text = qobject_cast<const QPlainTextEdit*>(w))
            add(key("plainText"), text->toPlainText());
        if (const auto* header = qobject_cast<const QHeaderView*>(w)) {
            if (const QAbstractItemModel* model = header->model()) {
                const int count = header->orientation() == Qt::Horizontal ? model->columnCount()
                                                                          : model->rowCount();
                for (int i = 0; i < count; ++i) {
                    if (header->isSectionHidden(i))
                        continue;
                    add(key("header"),
                        model->headerData(i, header->orientation(), Qt::DisplayRole).toString());
                    add(key("headerToolTip"),
                        model->headerData(i, header->orientation(), Qt::ToolTipRole).toString());
                }
            }
        } else if (const auto* view = qobject_cast<const QAbstractItemView*>(w)) {
            if (const QAbstractItemModel* model = view->model())
                cells(key("cell"), *model, QModelIndex());
        }
        if (const auto* plot = qobject_cast<const QCustomPlot*>(w))
            customPlot(at, *plot);
    }

    void cells(const QString& key, const QAbstractItemModel& model, const QModelIndex& parent)
    {
        for (int r = 0; r < model.rowCount(parent); ++r)
            for (int c = 0; c < model.columnCount(parent); ++c) {
                const QModelIndex index = model.index(r, c, parent);
                add(key, index.data(Qt::DisplayRole).toString());
                add(key + QStringLiteral("ToolTip"), index.data(Qt::ToolTipRole).toString());
                if (c == 0 && model.hasChildren(index))
                    cells(key, model, index);
            }
    }

    void customPlot(const QString& at, const QCustomPlot& plot)
    {
        for (QCPLayoutElement* e : plot.plotLayout()->elements(true)) {
            if (const auto* text = qobject_cast<const QCPTextElement*>(e))
                add(at + QStringLiteral("#plotText"), text->text());
            if (auto* item = qobject_cast<QCPPlottableLegendItem*>(e))
                add(at + QStringLiteral("#legend"), item->plottable()->name());
        }
        // The legend lays its items out itself; reach them through it too.
        for (int i = 0; i < plot.legend->itemCount(); ++i)
            if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot.legend->item(i)))
                add(at + QStringLiteral("#legend"), item->plottable()->name());
        for (const QCPAxisRect* rect : plot.axisRects())
            for (const QCPAxis* axis : rect->axes())
                add(at + QStringLiteral("#axis"), axis->label());
        for (int i = 0; i < plot.itemCount(); ++i)
            if (const auto* text = qobject_cast<const QCPItemText*>(plot.item(i)))
                if (text->visible())
                    add(at + QStringLiteral("#mark"), text->text());
    }

    void action(const QAction* a)
    {
        if (a->isSeparator())
            return;
        const QString at = path(a);
        add(at + QStringLiteral("#text"), a->text());
        // Without a tooltip of its own an action's tooltip is its text: listed once, as text.
        if (a->toolTip() != withoutMnemonics(a->text()))
            add(at + QStringLiteral("#toolTip"), a->toolTip());
        add(at + QStringLiteral("#statusTip"), a->statusTip());
        add(at + QStringLiteral("#whatsThis"), a->whatsThis());
    }

private:
    Texts& m_out;
};

/// Whether a student sees `w` or reaches it: visible, or inside a dock that waits behind
/// another in a tab group (its tab shows it).
bool reachable(const QWidget* w)
{
    if (w->isVisible())
        return true;
    for (const QWidget* p = w; p; p = p->parentWidget())
        if (const auto* dock = qobject_cast<const QDockWidget*>(p)) {
            // Behind a tab the dock's content is hidden: what it shows once chosen counts.
            const QWidget* content = dock->widget();
            const bool inContent =
                content && (w == content || (content->isAncestorOf(w) && w->isVisibleTo(content)));
            return dock->toggleViewAction()->isChecked() && !dock->isFloating() &&
                   dock->parentWidget() && dock->parentWidget()->isVisible() &&
                   (w == dock || inContent || w->isVisibleTo(dock));
        }
    return false;
}

/// Opens the context menu of `w` as a right click would and collects its actions' texts at
/// "<path of w>#contextMenu". A menu that runs its own loop (QMenu::exec) is closed from a timer
/// inside that loop; one that pops up is closed when the events are processed after.
bool contextMenu(QWidget* w, Collector& c)
{
    const QString key = Collector::path(w) + QStringLiteral("#contextMenu");
    bool opened = false;
    QTimer::singleShot(0, w, [&] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        if (!menu)
            return;
        opened = true;
        for (const QAction* a : menu->actions())
            if (!a->isSeparator())
                c.add(key, a->text());
        menu->close();
    });
    const QPoint at = w->rect().center();
    if (w->contextMenuPolicy() == Qt::CustomContextMenu) {
        emit w->customContextMenuRequested(at);
    } else {
        QContextMenuEvent event(QContextMenuEvent::Keyboard, at, w->mapToGlobal(at));
        QCoreApplication::sendEvent(w, &event);
    }
    QCoreApplication::processEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    return opened;
}

/// The context menus of RigidLab's own widgets that the window shows (plots, tables, panels).
void contextMenus(MainWindow& window, Collector& c)
{
    QList<QWidget*> targets;
    for (QWidget* w : window.findChildren<QWidget*>()) {
        if (!w->isVisible() || qobject_cast<QMenu*>(w))
            continue;
        const bool own = QByteArray(w->metaObject()->className()).startsWith("rigidlab::ui::");
        // RigidLab's tables (FittingTable) open theirs in contextMenuEvent.
        if (w->contextMenuPolicy() == Qt::CustomContextMenu ||
            (own && qobject_cast<QTableWidget*>(w)))
            targets << w;
    }
    for (QWidget* w : std::as_const(targets))
        if (!contextMenu(w, c))
            qWarning("no context menu opened on %s", qPrintable(Collector::path(w)));
}

/// Every text of the window that a student can see or open.
Texts collect(MainWindow& window)
{
    Texts out;
    Collector c(out);
    c.widget(&window);
    for (const QWidget* w : window.findChildren<QWidget*>()) {
        if (Collector::insideInvariant(w))
            continue;
        // Menus are hidden until opened: their titles count all the same.
        if (const auto* menu = qobject_cast<const QMenu*>(w)) {
            c.add(Collector::path(menu) + QStringLiteral("#title"), menu->title());
            continue;
        }
        if (reachable(w))
            c.widget(w);
    }
    for (const QAction* a : window.findChildren<QAction*>())
        if (!Collector::insideInvariant(a))
            c.action(a);
    contextMenus(window, c);
    return out;
}

/// The texts of a window in `language` at every place: the welcome scene, then each step of each
/// shipped lesson ("lesson.json step N"), in that order.
QList<std::pair<QString, Texts>> textsOfWindow(const QString& language)
{
    QList<std::pair<QString, Texts>> out;
    if (!ui::applyLanguage(language)) {
        QTest::qFail(qPrintable(QStringLiteral("no language ") + language), __FILE__, __LINE__);
        return out;
    }
    // Both windows start alike: no recent files, no saved layout of an earlier window.
    QSettings().clear();
    MainWindow w;
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    if (!QTest::qWaitForWindowExposed(&w)) {
        QTest::qFail("the window was not shown", __FILE__, __LINE__);
        return out;
    }
    const QString welcome =
        QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json"));
    if (const QString error = w.openScene(welcome, true); !error.isEmpty()) {
        QTest::qFail(qPrintable(error), __FILE__, __LINE__);
        return out;
    }
    QCoreApplication::processEvents();
    out.append({QStringLiteral("welcome scene"), collect(w)});
    test::visitShippedSteps(w, [&](const QString& path, int index, const auto&) {
        out.append({QStringLiteral("%1 step %2").arg(QFileInfo(path).fileName()).arg(index + 1),
                    collect(w)});
    });
    if (auto* help = w.findChild<QAction*>(QStringLiteral("help"))) // Help › Controls (F1)
        help->trigger();
    QCoreApplication::processEvents();
    out.append({QStringLiteral("Help › Controls"), collect(w)});
    return out;
}

/// How many texts of these places have a Czech letter (the English check's check).
qsizetype czechPieces(const QList<std::pair<QString, Texts>>& places)
{
    qsizetype n = 0;
    for (const auto& place : places)
        for (const QStringList& texts : place.second)
            n += std::count_if(texts.cbegin(), texts.cend(), hasCzechLetter);
    return n;
}

/// At most `cap` lines of `lines`, and how many more there are.
QString capped(const QStringList& lines, int cap)
{
    QStringList shown = lines.mid(0, cap);
    if (lines.size() > cap)
        shown << QStringLiteral("... and %1 more").arg(lines.size() - cap);
    return shown.join(u'\n');
}

} // namespace

class TestUntranslated : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QElapsedTimer timer;
        timer.start();
        m_english = textsOfWindow(QStringLiteral("en"));
        QVERIFY(!QTest::currentTestFailed());
        m_czech = textsOfWindow(QStringLiteral("cs"));
        QVERIFY(!QTest::currentTestFailed());
        ui::applyLanguage(QStringLiteral("en"));
        // The same places in both languages: the welcome scene and every step of every lesson.
        QCOMPARE(m_czech.size(), m_english.size());
        QVERIFY(m_english.size() > 10);
        for (int i = 0; i < m_english.size(); ++i)
            QCOMPARE(m_czech[i].first, m_english[i].first);
        qsizetype pieceCount = 0;
        for (const auto& place : std::as_const(m_czech))
            for (const QStringList& texts : place.second)
                pieceCount += texts.size();
        qInfo("both windows walked in %lld ms: %lld places, %lld Czech texts",
              static_cast<long long>(timer.elapsed()), static_cast<long long>(m_czech.size()),
              static_cast<long long>(pieceCount));
    }
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }

    // The Czech window shows no English: a text identical in both languages at the same place
    // is English left untranslated, unless it reads the same in Czech (invariant()).
    void czechWindowHasNoEnglish()
    {
        // key + text -> where it was first seen, so a menu left in English is listed once.
        QMap<QString, QString> untranslated;
        QStringList order;
        int keysCompared = 0;
        for (int p = 0; p < m_english.size(); ++p) {
            const Texts& en = m_english[p].second;
            const Texts& cs = m_czech[p].second;
            for (auto it = en.cbegin(); it != en.cend(); ++it) {
                const auto found = cs.constFind(it.key());
                if (found == cs.cend())
                    continue; // shown in English only (a widget the Czech layout hid)
                ++keysCompared;
                for (const QString& piece : it.value()) {
                    if (invariant(piece) || !found->contains(piece))
                        continue;
                    const QString id = it.key() + QStringLiteral(": \"") + piece + u'"';
                    if (!untranslated.contains(id)) {
                        untranslated.insert(id, m_english[p].first);
                        order << id;
                    }
                }
            }
        }
        // Not vacuous: the places and their texts were found and paired, context menus too.
        QVERIFY(std::any_of(m_english.cbegin(), m_english.cend(), [](const auto& place) {
            return std::any_of(place.second.keyBegin(), place.second.keyEnd(),
                               [](const QString& k) { return k.endsWith(u"#contextMenu"); });
        }));
        QVERIFY2(keysCompared > 1000, qPrintable(QString::number(keysCompared)));
        QStringList lines;
        for (const QString& id : order)
            lines << QStringLiteral("[%1] %2").arg(untranslated.value(id), id);
        const QString message =
            QStringLiteral("%1 texts of the Czech window are still English:\n").arg(lines.size()) +
            capped(lines, 200);
        if constexpr (kRequireCompleteCzech)
            QVERIFY2(lines.isEmpty(), qPrintable(message));
        else if (!lines.isEmpty())
            QWARN(qPrintable(message));
    }

    // The English window shows no Czech letter (the Language menu's "Čeština" is its own name).
    void englishWindowHasNoCzech()
    {
        QVERIFY2(czechPieces(m_czech) > 100, "the Czech window should show Czech letters");
        QStringList found;
        QSet<QString> seen;
        for (const auto& [where, texts] : std::as_const(m_english))
            for (auto it = texts.cbegin(); it != texts.cend(); ++it)
                for (const QString& piece : it.value()) {
                    const bool czech = hasCzechLetter(piece);
                    const QString id = it.key() + QStringLiteral(": \"") + piece + u'"';
                    if (czech && !seen.contains(id)) {
                        seen.insert(id);
                        found << QStringLiteral("[%1] %2").arg(where, id);
                    }
                }
        QVERIFY2(
            found.isEmpty(),
            qPrintable(
                QStringLiteral("%1 texts of the English window are Czech:\n").arg(found.size()) +
                capped(found, 100)));
    }

private:
    QList<std::pair<QString, Texts>> m_english;
    QList<std::pair<QString, Texts>> m_czech;
};

RIGIDLAB_TEST_MAIN(TestUntranslated)
#include "test_untranslated.moc"
