#pragma once
// Every control of the window has an accessible name, so a screen reader says what it is and
// not only "combo box". Most controls are named where they are made (a button's text, a form
// label that is the field's buddy, an explicit setAccessibleName); nameControls() is the net
// under them: a control that would still have no name gets one from what a sighted user reads
// beside it (the form label, its tooltip's first line, a line edit's placeholder, the group or
// dock it sits in), and its tooltip as its description. Widgets that do not take the keyboard
// focus are left alone.

#include <QString>

class QWidget;

namespace phasebox::ui {

// The name a screen reader announces for w ("" when it has none).
QString accessibleNameOf(QWidget* w);

// Names every focusable descendant of root (root included) that has no accessible name yet;
// call it again after adding controls.
void nameControls(QWidget* root);

}  // namespace phasebox::ui
