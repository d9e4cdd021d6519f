<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>CommandLine</name>
    <message numerus="yes">
        <source>%n file(s) written into %1</source>
        <translation>
            <numerusform>%n file written into %1</numerusform>
            <numerusform>%n files written into %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SceneWords</name>
    <message numerus="yes">
        <source>On stage: %n moving body(ies)</source>
        <translation>
            <numerusform>On stage: %n moving body</numerusform>
            <numerusform>On stage: %n moving bodies</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n fixed body(ies).</source>
        <translation>
            <numerusform>, %n fixed body.</numerusform>
            <numerusform>, %n fixed bodies.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n pair(s) of bodies touch.</source>
        <translation>
            <numerusform>%n pair of bodies touches.</numerusform>
            <numerusform>%n pairs of bodies touch.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>polygon, %n corner(s)</source>
        <translation>
            <numerusform>polygon, %n corner</numerusform>
            <numerusform>polygon, %n corners</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::ControlPanel</name>
    <message numerus="yes">
        <source>Soft step: iterations of its bounce pass at the start of each step; the resting contacts are solved in %n substeps instead</source>
        <translation>
            <numerusform>Soft step: iterations of its bounce pass at the start of each step; the resting contacts are solved in %n substep instead</numerusform>
            <numerusform>Soft step: iterations of its bounce pass at the start of each step; the resting contacts are solved in %n substeps instead</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::EditTools</name>
    <message numerus="yes">
        <source>%n point(s); double-click or Enter closes the polygon, Escape drops it</source>
        <translation>
            <numerusform>%n point; double-click or Enter closes the polygon, Escape drops it</numerusform>
            <numerusform>%n points; double-click or Enter closes the polygon, Escape drops it</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::LessonEditor</name>
    <message numerus="yes">
        <source>%n problem(s)</source>
        <translation>
            <numerusform>%n problem</numerusform>
            <numerusform>%n problems</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::MeasurementFit</name>
    <message numerus="yes">
        <source>Residual RMS: %1 over %n point(s)</source>
        <translation>
            <numerusform>Residual RMS: %1 over %n point</numerusform>
            <numerusform>Residual RMS: %1 over %n points</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::MeasurementImportDialog</name>
    <message numerus="yes">
        <source>%n bounce time(s)</source>
        <translation>
            <numerusform>%n bounce time</numerusform>
            <numerusform>%n bounce times</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n point</numerusform>
            <numerusform>%n points</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n row(s) before time zero left out</source>
        <translation>
            <numerusform>%n row before time zero left out</numerusform>
            <numerusform>%n rows before time zero left out</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::MeasurementPanel</name>
    <message numerus="yes">
        <source>Fitting… %n run(s) of the model so far</source>
        <translation>
            <numerusform>Fitting… %n run of the model so far</numerusform>
            <numerusform>Fitting… %n runs of the model so far</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::MeasurementSession</name>
    <message numerus="yes">
        <source>%1: %n point(s) of %2</source>
        <translation>
            <numerusform>%1: %n point of %2</numerusform>
            <numerusform>%1: %n points of %2</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::SimulationController</name>
    <message numerus="yes">
        <source>%n iteration(s)</source>
        <translation>
            <numerusform>%n iteration</numerusform>
            <numerusform>%n iterations</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::StatusLine</name>
    <message numerus="yes">
        <source> · %1 error estimate %2 (%Ln substep(s))</source>
        <translation>
            <numerusform> · %1 error estimate %2 (%Ln substep)</numerusform>
            <numerusform> · %1 error estimate %2 (%Ln substeps)</numerusform>
        </translation>
    </message>
</context>
</TS>
