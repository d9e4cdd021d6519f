<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ">
<context>
    <name>About</name>
    <message>
        <source>&lt;h3&gt;RigidLab %1&lt;/h3&gt;&lt;p&gt;A lab for teaching 2D rigid-body mechanics: integrators and their energy drift, collision detection by separating axes, and impulses.&lt;/p&gt;&lt;p&gt;It grows from the paper &lt;i&gt;Simulace mechaniky tuhých těles v reálném čase&lt;/i&gt; (&lt;i&gt;Real-time simulation of rigid-body mechanics&lt;/i&gt;).&lt;/p&gt;&lt;p&gt;Licence: GNU General Public License, version 3 or any later version (GPL-3.0-or-later), as QCustomPlot, which it links, requires. See the LICENSE file.&lt;/p&gt;&lt;p&gt;Built with Qt %2 (running on Qt %3), QCustomPlot %4 and Eigen %5.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;RigidLab %1&lt;/h3&gt;&lt;p&gt;Laboratoř pro výuku mechaniky tuhých těles ve 2D: integrátory a&#xa0;jejich energetický drift, detekce srážek pomocí oddělujících os a&#xa0;impulsy síly.&lt;/p&gt;&lt;p&gt;Vychází z&#xa0;článku &lt;i&gt;Simulace mechaniky tuhých těles v&#xa0;reálném čase&lt;/i&gt;.&lt;/p&gt;&lt;p&gt;Licence: GNU General Public License, verze 3 nebo jakákoli pozdější verze (GPL-3.0-or-later), jak to vyžaduje knihovna QCustomPlot, se kterou je program sestaven. Viz soubor LICENSE.&lt;/p&gt;&lt;p&gt;Sestaveno s&#xa0;Qt %2 (běží na Qt %3), QCustomPlot %4 a&#xa0;Eigen %5.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>About RigidLab</source>
        <translation>O&#xa0;aplikaci RigidLab</translation>
    </message>
</context>
<context>
    <name>AccessibleNames</name>
    <message>
        <source>Scroll %1</source>
        <translation>Posouvat panel %1</translation>
    </message>
    <message>
        <source>Scroll %1 sideways</source>
        <translation>Posouvat panel %1 do stran</translation>
    </message>
</context>
<context>
    <name>ChoiceQuestion</name>
    <message>
        <source>Right answer: “%1”</source>
        <translation>Správná odpověď: „%1“</translation>
    </message>
    <message>
        <source>a choice of answers</source>
        <translation>výběr z odpovědí</translation>
    </message>
    <message>
        <source>The right option</source>
        <translation>Správná možnost</translation>
    </message>
    <message>
        <source>The student chooses one of %1 options; the right one is “%2”.</source>
        <translation>Žák volí jednu z %1 možností; správná je „%2“.</translation>
    </message>
</context>
<context>
    <name>ClassResults</name>
    <message>
        <source>no lesson &quot;%1&quot; among the shipped lessons and your own (name its file)</source>
        <translation>lekce „%1“ není mezi dodanými ani vašimi vlastními lekcemi (zadejte její soubor)</translation>
    </message>
    <message>
        <source>%1: answers to &quot;%2&quot;, not to &quot;%3&quot;: left out</source>
        <translation>%1: odpovědi k „%2“, ne k „%3“: vynecháno</translation>
    </message>
    <message>
        <source>%1: %2 (the lesson has changed since?)</source>
        <translation>%1: %2 (změnila se mezitím lekce?)</translation>
    </message>
    <message>
        <source>%1: no such folder</source>
        <translation>%1: taková složka není</translation>
    </message>
    <message>
        <source>%1: the folder cannot be read</source>
        <translation>%1: složku nelze číst</translation>
    </message>
    <message>
        <source>%1: no answers files (%2) in it</source>
        <translation>%1: nejsou v ní soubory s odpověďmi (%2)</translation>
    </message>
    <message>
        <source>%1: none of its %2 answers files reads</source>
        <translation>%1: žádný z jejích %2 souborů s odpověďmi nelze přečíst</translation>
    </message>
    <message>
        <source>%1: its answers name no lesson (name the lesson&apos;s file)</source>
        <translation>%1: odpovědi neuvádějí lekci (zadejte soubor lekce)</translation>
    </message>
    <message>
        <source>%1: no answers to &quot;%2&quot; in it</source>
        <translation>%1: nejsou v ní odpovědi k „%2“</translation>
    </message>
    <message>
        <source>✓ right</source>
        <translation>✓ správně</translation>
    </message>
    <message>
        <source>✗ not right</source>
        <translation>✗ nesprávně</translation>
    </message>
    <message>
        <source>… not measured yet</source>
        <translation>… ještě nezměřeno</translation>
    </message>
    <message>
        <source>— not answered</source>
        <translation>— bez odpovědi</translation>
    </message>
    <message>
        <source>hint, Show me</source>
        <translation>nápověda, Ukaž mi</translation>
    </message>
    <message>
        <source>hint</source>
        <translation>nápověda</translation>
    </message>
    <message>
        <source>Show me</source>
        <translation>Ukaž mi</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Jméno</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Třída</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <source>%1 first answer</source>
        <translation>%1 první odpověď</translation>
    </message>
    <message>
        <source>%1 first answer [%2]</source>
        <translation>%1 první odpověď [%2]</translation>
    </message>
    <message>
        <source>%1 verdict</source>
        <translation>%1 hodnocení</translation>
    </message>
    <message>
        <source>%1 tries</source>
        <translation>%1 pokusy</translation>
    </message>
    <message>
        <source>%1 hint or Show me</source>
        <translation>%1 nápověda nebo Ukaž mi</translation>
    </message>
    <message>
        <source>Right at the first answer [%]</source>
        <translation>Správně napoprvé [%]</translation>
    </message>
    <message>
        <source>%1 % (%2 of %3)</source>
        <translation>%1 % (%2 z %3)</translation>
    </message>
</context>
<context>
    <name>ClassResultsText</name>
    <message>
        <source>Students: %1. Each question&apos;s cell: the first answer, its verdict, the tries, hint or Show me used.</source>
        <translation>Žáků: %1. V buňce každé otázky: první odpověď, její hodnocení, počet pokusů, použitá nápověda nebo Ukaž mi.</translation>
    </message>
    <message>
        <source>Files left out</source>
        <translation>Vynechané soubory</translation>
    </message>
    <message>
        <source>Class results</source>
        <translation>Výsledky třídy</translation>
    </message>
    <message>
        <source>Class results: %1</source>
        <translation>Výsledky třídy: %1</translation>
    </message>
    <message>
        <source>cannot write %1: could not start drawing the PDF</source>
        <translation>nelze zapsat %1: kreslení PDF nešlo začít</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <source>RigidLab %1: a lab for 2D rigid-body mechanics.</source>
        <translation>RigidLab %1: laboratoř mechaniky tuhých těles ve 2D.</translation>
    </message>
    <message>
        <source>Show this text and quit.</source>
        <translation>Vypsat tento text a&#xa0;skončit.</translation>
    </message>
    <message>
        <source>Show the version and quit.</source>
        <translation>Vypsat verzi a&#xa0;skončit.</translation>
    </message>
    <message>
        <source>With a lesson: start at step N (1 = first).</source>
        <translation>S&#xa0;lekcí: začít krokem N (1 = první).</translation>
    </message>
    <message>
        <source>Run the scene for N frames, print the median and 95th-percentile frame time and the physics share, and quit.</source>
        <translation>Přehrát N snímků scény, vypsat medián a&#xa0;95. percentil doby snímku a&#xa0;podíl fyziky a&#xa0;skončit.</translation>
    </message>
    <message>
        <source>Write a PNG of the window on the welcome scene and on every step of every shipped lesson into DIR, with DIR/index.txt, and quit.</source>
        <translation>Uložit do složky DIR snímek okna (PNG) s&#xa0;uvítací scénou a&#xa0;s&#xa0;každým krokem každé dodané lekce, k&#xa0;tomu DIR/index.txt, a&#xa0;skončit.</translation>
    </message>
    <message>
        <source>Window (and screenshot) size in pixels, e.g. 1024x768 (screenshots: 1280x720 unless given).</source>
        <translation>Velikost okna (a&#xa0;snímků) v&#xa0;pixelech, např. 1024x768 (snímky: 1280x720, pokud není zadána).</translation>
    </message>
    <message>
        <source>Scale factor of the whole interface (QT_SCALE_FACTOR), e.g. 1.5.</source>
        <translation>Měřítko celého rozhraní (QT_SCALE_FACTOR), např. 1.5.</translation>
    </message>
    <message>
        <source>Presentation mode: full screen, large type and thick lines for a projector (F11).</source>
        <translation>Režim prezentace: celá obrazovka, velké písmo a&#xa0;silné čáry pro projektor (F11).</translation>
    </message>
    <message>
        <source>--%1 needs %2, got &quot;%3&quot;</source>
        <translation>--%1 vyžaduje %2, zadáno „%3“</translation>
    </message>
    <message>
        <source>a whole number from 1</source>
        <translation>celé číslo od 1</translation>
    </message>
    <message>
        <source>WIDTHxHEIGHT in pixels, each from %1 to %2</source>
        <translation>ŠÍŘKAxVÝŠKA v&#xa0;pixelech, obojí od %1 do %2</translation>
    </message>
    <message>
        <source>a number greater than 0 and at most %1</source>
        <translation>číslo větší než 0 a&#xa0;nejvýše %1</translation>
    </message>
    <message>
        <source>a folder</source>
        <translation>složku</translation>
    </message>
    <message>
        <source>%1 (try rigidlab --help)</source>
        <translation>%1 (zkuste rigidlab --help)</translation>
    </message>
    <message>
        <source>one file at a time (got %1 and %2)</source>
        <translation>jen jeden soubor najednou (zadáno %1 a&#xa0;%2)</translation>
    </message>
    <message>
        <source>--measure-frames needs a scene to run</source>
        <translation>--measure-frames vyžaduje scénu, kterou přehraje</translation>
    </message>
    <message>
        <source>--screenshots shoots the shipped scenes and lessons: give it no FILE and no --measure-frames</source>
        <translation>--screenshots snímá dodané scény a&#xa0;lekce: nezadávejte k&#xa0;ní FILE ani --measure-frames</translation>
    </message>
    <message>
        <source>no display to open the window on: set DISPLAY (an X server, or Xvfb) or WAYLAND_DISPLAY, or QT_QPA_PLATFORM=offscreen</source>
        <translation>není displej, na kterém by se otevřelo okno: nastavte DISPLAY (X server nebo Xvfb) nebo WAYLAND_DISPLAY, případně QT_QPA_PLATFORM=offscreen</translation>
    </message>
    <message numerus="yes">
        <source>%n file(s) written into %1</source>
        <translation>
            <numerusform>%n soubor zapsán do %1</numerusform>
            <numerusform>%n soubory zapsány do %1</numerusform>
            <numerusform>%n souborů zapsáno do %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Language of the interface, one of %1 (View › Language saves a choice; without either, the system&apos;s language).</source>
        <translation>Jazyk rozhraní, jeden z&#xa0;kódů %1 (volbu uloží i&#xa0;Zobrazení › Jazyk; bez obojího jazyk systému).</translation>
    </message>
    <message>
        <source>one of %1</source>
        <translation>jeden z&#xa0;kódů %1</translation>
    </message>
    <message>
        <source>A scene or a lesson (FILE.json, or FILE.rlesson) to open.</source>
        <translation>Scéna nebo lekce (FILE.json nebo FILE.rlesson), která se má otevřít.</translation>
    </message>
</context>
<context>
    <name>Controls</name>
    <message>
        <source> or </source>
        <translation> nebo </translation>
    </message>
    <message>
        <source>Keyboard</source>
        <translation>Klávesnice</translation>
    </message>
    <message>
        <source>Mouse</source>
        <translation>Myš</translation>
    </message>
    <message>
        <source>Play or pause the simulation</source>
        <translation>Spustit nebo pozastavit simulaci</translation>
    </message>
    <message>
        <source>One step forward (pauses)</source>
        <translation>O&#xa0;jeden krok vpřed (pozastaví)</translation>
    </message>
    <message>
        <source>One step back in time</source>
        <translation>O&#xa0;jeden krok zpět v&#xa0;čase</translation>
    </message>
    <message>
        <source>Back to the start of the scene</source>
        <translation>Zpět na začátek scény</translation>
    </message>
    <message>
        <source>Zoom to show every body</source>
        <translation>Přiblížit tak, aby byla vidět všechna tělesa</translation>
    </message>
    <message>
        <source>Turn the selected body left by 5°</source>
        <translation>Otočit vybrané těleso o&#xa0;5° doleva</translation>
    </message>
    <message>
        <source>Turn the selected body right by 5°</source>
        <translation>Otočit vybrané těleso o&#xa0;5° doprava</translation>
    </message>
    <message>
        <source>Presentation mode: full screen, large type and thick lines for a projector</source>
        <translation>Režim prezentace: celá obrazovka, velké písmo a&#xa0;silné čáry pro projektor</translation>
    </message>
    <message>
        <source>Open a scene</source>
        <translation>Otevřít scénu</translation>
    </message>
    <message>
        <source>Open a lesson</source>
        <translation>Otevřít lekci</translation>
    </message>
    <message>
        <source>Quit RigidLab</source>
        <translation>Ukončit RigidLab</translation>
    </message>
    <message>
        <source>Click a body</source>
        <translation>Kliknout na těleso</translation>
    </message>
    <message>
        <source>Select it and show it in the inspector</source>
        <translation>Vybrat ho a&#xa0;zobrazit v&#xa0;Inspektoru</translation>
    </message>
    <message>
        <source>Drag a body</source>
        <translation>Táhnout těleso</translation>
    </message>
    <message>
        <source>Pull it with a spring; release to throw it</source>
        <translation>Táhnout ho pružinou; puštěním ho hodit</translation>
    </message>
    <message>
        <source>Drag empty space or the middle button</source>
        <translation>Táhnout za prázdné místo nebo se stisknutým prostředním tlačítkem</translation>
    </message>
    <message>
        <source>Pan the view</source>
        <translation>Posunout pohled</translation>
    </message>
    <message>
        <source>Mouse wheel</source>
        <translation>Kolečko myši</translation>
    </message>
    <message>
        <source>Zoom about the pointer</source>
        <translation>Přiblížit nebo oddálit kolem ukazatele</translation>
    </message>
    <message>
        <source>Drag the timeline</source>
        <translation>Táhnout časovou osu</translation>
    </message>
    <message>
        <source>Go back to any earlier moment of the run</source>
        <translation>Vrátit se k&#xa0;libovolnému dřívějšímu okamžiku běhu</translation>
    </message>
    <message>
        <source>Edit mode on or off: draw the scene; leaving it loads the scene as edited, paused</source>
        <translation>Editor zapnout nebo vypnout: kreslit scénu; po jeho vypnutí se načte upravená scéna, zastavená</translation>
    </message>
    <message>
        <source>Edit: select and move bodies (arrows nudge)</source>
        <translation>Editor: vybírat a&#xa0;posouvat tělesa (šipky posunou o&#xa0;kousek)</translation>
    </message>
    <message>
        <source>Edit: turn a body by dragging (Q, E by 5°)</source>
        <translation>Editor: otáčet tělesem tažením (Q, E o&#xa0;5°)</translation>
    </message>
    <message>
        <source>Edit: draw a circle from its centre</source>
        <translation>Editor: kreslit kruh od středu</translation>
    </message>
    <message>
        <source>Edit: draw a box</source>
        <translation>Editor: kreslit obdélník</translation>
    </message>
    <message>
        <source>Edit: draw a polygon (Enter closes it)</source>
        <translation>Editor: kreslit mnohoúhelník (Enter ho uzavře)</translation>
    </message>
    <message>
        <source>Edit: draw static ground or a wall</source>
        <translation>Editor: kreslit statickou podložku nebo stěnu</translation>
    </message>
    <message>
        <source>Edit: pin a body to another or to the world</source>
        <translation>Editor: připojit těleso čepem k&#xa0;jinému tělesu nebo k&#xa0;okolí</translation>
    </message>
    <message>
        <source>Edit: draw a spring</source>
        <translation>Editor: kreslit pružinu</translation>
    </message>
    <message>
        <source>Edit: click bodies to delete them</source>
        <translation>Editor: kliknutím tělesa smazat</translation>
    </message>
    <message>
        <source>Edit: click bodies to duplicate them</source>
        <translation>Editor: kliknutím tělesa duplikovat</translation>
    </message>
    <message>
        <source>Edit: snap to the grid and to corners, on or off</source>
        <translation>Editor: přichytávání k&#xa0;mřížce a&#xa0;k&#xa0;rohům zapnout nebo vypnout</translation>
    </message>
    <message>
        <source>Edit: delete the selected body</source>
        <translation>Editor: smazat vybrané těleso</translation>
    </message>
    <message>
        <source>Undo the last edit of the scene</source>
        <translation>Vrátit poslední úpravu scény</translation>
    </message>
    <message>
        <source>Redo the edit undone last</source>
        <translation>Znovu provést naposledy vrácenou úpravu</translation>
    </message>
    <message>
        <source>A new, empty scene</source>
        <translation>Nová, prázdná scéna</translation>
    </message>
    <message>
        <source>Save the scene</source>
        <translation>Uložit scénu</translation>
    </message>
    <message>
        <source>Save the scene under another name</source>
        <translation>Uložit scénu pod jiným jménem</translation>
    </message>
    <message>
        <source>Help: this list of keys and mouse actions</source>
        <translation>Nápověda: tento přehled kláves a&#xa0;ovládání myší</translation>
    </message>
    <message>
        <source>Import a measurement (CSV) to compare and fit</source>
        <translation>Importovat měření (CSV) k&#xa0;porovnání a&#xa0;určení parametrů</translation>
    </message>
    <message>
        <source>Drop a CSV file on the window</source>
        <translation>Přetáhnout soubor CSV do okna</translation>
    </message>
    <message>
        <source>Import it as a measurement</source>
        <translation>Importovat ho jako měření</translation>
    </message>
    <message>
        <source>Hand in the lesson&apos;s worksheet (PDF)</source>
        <translation>Odevzdat pracovní list lekce (PDF)</translation>
    </message>
    <message>
        <source>The lesson&apos;s next step</source>
        <translation>Další krok lekce</translation>
    </message>
    <message>
        <source>The lesson&apos;s previous step</source>
        <translation>Předchozí krok lekce</translation>
    </message>
    <message>
        <source>Put the keyboard focus on the scene</source>
        <translation>Přesunout fokus klávesnice na scénu</translation>
    </message>
    <message>
        <source>Select the next body (in the scene: arrows move it, Shift+arrows change its velocity, Enter shows its numbers, Esc lets it go)</source>
        <translation>Vybrat další těleso (ve scéně: šipky ho posunou, Shift+šipky změní jeho rychlost, Enter ukáže jeho hodnoty, Esc ho pustí)</translation>
    </message>
    <message>
        <source>Select the previous body</source>
        <translation>Vybrat předchozí těleso</translation>
    </message>
    <message>
        <source>Single-key shortcuts (letters, Space, arrows) on or off</source>
        <translation>Jednoklávesové zkratky (písmena, mezerník, šipky) zapnout nebo vypnout</translation>
    </message>
    <message>
        <source>Instruments on the scene: ruler, protractor, stopwatch, probe, frame of reference</source>
        <translation>Měřidla ve scéně: pravítko, úhloměr, stopky, sonda, vztažná soustava</translation>
    </message>
    <message>
        <source>A graph of chosen bodies&apos; quantities against time</source>
        <translation>Graf veličin vybraných těles v závislosti na čase</translation>
    </message>
    <message>
        <source>Put the keyboard focus on the toolbar: arrows move between its buttons, Space or Enter presses one, Esc goes back</source>
        <translation>Přesunout fokus klávesnice na panel nástrojů: šipky přecházejí mezi jeho tlačítky, mezerník nebo Enter jedno stiskne, Esc vrátí fokus zpět</translation>
    </message>
    <message>
        <source>Edit: add a circle, a box, a polygon or ground at the view&apos;s centre (a menu)</source>
        <translation>Editor: přidat kruh, obdélník, mnohoúhelník nebo podložku doprostřed pohledu (nabídka)</translation>
    </message>
    <message>
        <source>Edit: zoom in or out about the middle of the view</source>
        <translation>Editor: přiblížit nebo oddálit kolem středu pohledu</translation>
    </message>
    <message>
        <source>Edit: zoom to show every body</source>
        <translation>Editor: přiblížit tak, aby byla vidět všechna tělesa</translation>
    </message>
    <message>
        <source>Edit: pan the view</source>
        <translation>Editor: posunout pohled</translation>
    </message>
    <message>
        <source>Back to the lesson editor, at the step the student is on (while trying a lesson from it)</source>
        <translation>Zpět do editoru lekcí, na krok, na kterém je žák (při zkoušení lekce z editoru)</translation>
    </message>
</context>
<context>
    <name>CsvColumns</name>
    <message>
        <source>step</source>
        <translation>krok</translation>
    </message>
    <message>
        <source>body</source>
        <translation>těleso</translation>
    </message>
    <message>
        <source>angle [rad]</source>
        <translation>úhel [rad]</translation>
    </message>
    <message>
        <source>contacts</source>
        <translation>kontakty</translation>
    </message>
    <message>
        <source>drift [1]</source>
        <translation>drift [1]</translation>
    </message>
    <message>
        <source>drift [%]</source>
        <translation>drift [%]</translation>
    </message>
</context>
<context>
    <name>DivergenceWords</name>
    <message>
        <source>position</source>
        <translation>poloha</translation>
    </message>
    <message>
        <source>angle</source>
        <translation>úhel</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>rychlost</translation>
    </message>
    <message>
        <source>angular velocity</source>
        <translation>úhlová rychlost</translation>
    </message>
    <message>
        <source>total energy</source>
        <translation>celková energie</translation>
    </message>
    <message>
        <source>the total energy is no longer finite</source>
        <translation>celková energie už není konečné číslo</translation>
    </message>
    <message>
        <source>energy blew up</source>
        <translation>energie „vybuchla“</translation>
    </message>
    <message>
        <source>%1 no longer finite</source>
        <translation>%1 už není konečné číslo</translation>
    </message>
    <message>
        <source>stopped at t = %1 s: %2</source>
        <translation>zastaveno v&#xa0;čase t = %1&#xa0;s: %2</translation>
    </message>
    <message>
        <source>body &quot;%1&quot;: %2 is no longer finite</source>
        <translation>těleso „%1“: %2 už není konečné číslo</translation>
    </message>
    <message>
        <source>the total energy grew to %1 J, past the bound of %2 J</source>
        <translation>celková energie vzrostla na %1&#xa0;J, přes mez %2&#xa0;J</translation>
    </message>
    <message>
        <source> (body &quot;%1&quot; holds the most kinetic energy)</source>
        <translation> (největší kinetickou energii má těleso „%1“)</translation>
    </message>
    <message>
        <source>diverged at t = %1 s (step %2, dt = %3 s, %4): %5</source>
        <translation>divergovala v&#xa0;čase t = %1&#xa0;s (krok %2, dt = %3&#xa0;s, %4): %5</translation>
    </message>
    <message>
        <source>The simulation %1. It stopped here rather than draw garbage.</source>
        <translation>Simulace %1. Zastavila se tady, aby nekreslila nesmysly.</translation>
    </message>
    <message>
        <source>pairs of bodies</source>
        <translation>dvojice těles</translation>
    </message>
    <message>
        <source>more than %1 pairs of bodies overlap or nearly touch (around body &quot;%2&quot;): so crowded a scene needs memory and time growing with the square of the bodies; spread them out</source>
        <translation>víc než %1 dvojic těles se překrývá nebo téměř dotýká (kolem tělesa „%2“): tak nahuštěná scéna potřebuje paměť a čas rostoucí se čtvercem počtu těles; rozmístěte je</translation>
    </message>
    <message>
        <source>stopped at t = %1 s, before step %2: %3</source>
        <translation>zastavila se v&#xa0;čase t = %1&#xa0;s, před krokem %2: %3</translation>
    </message>
    <message>
        <source>The simulation %1. It stopped here rather than freeze the computer.</source>
        <translation>Simulace %1. Zastavila se tady, aby nezamrzl počítač.</translation>
    </message>
    <message>
        <source>too crowded to run</source>
        <translation>příliš nahuštěná</translation>
    </message>
</context>
<context>
    <name>DrawableWords</name>
    <message>
        <source>[U+%1]</source>
        <translation>[U+%1]</translation>
    </message>
</context>
<context>
    <name>DriftWords</name>
    <message>
        <source>energy drift %1 %</source>
        <translation>energetický drift %1&#xa0;%</translation>
    </message>
    <message>
        <source>energy drift (integrator, contacts, joints) %1 %</source>
        <translation>energetický drift (integrátor, kontakty, klouby) %1&#xa0;%</translation>
    </message>
    <message>
        <source>&lt;p&gt;Energy drift: how far the total energy (motion, height, springs) has moved from its value at the start, as a share of it, after adding back what bounces, friction, drag and dampers took. Exact physics would keep it at 0.&lt;/p&gt;&lt;p&gt;What is left is numerical error: the integrator&apos;s, step by step; that of the corrections after contacts and joints are solved (bodies that sank into each other are pushed apart, pins are pulled back together); and that of the estimate of what the contacts took, which grows steadily while bodies rest on each other. A method that follows a free fall exactly, such as velocity Verlet, still drifts where bodies touch.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Energetický drift: o&#xa0;kolik se celková energie (pohyb, výška, pružiny) změnila od začátku, jako podíl počáteční hodnoty, po přičtení toho, co odebraly odrazy, tření, odpor prostředí a&#xa0;tlumiče. Přesná fyzika by ho udržela na 0.&lt;/p&gt;&lt;p&gt;Co zbývá, je numerická chyba: chyba integrátoru krok za krokem; chyba oprav po vyřešení kontaktů a&#xa0;kloubů (tělesa, která se do sebe zabořila, se odsunou od sebe, čepy se přitáhnou zpět k&#xa0;sobě); a&#xa0;chyba odhadu toho, co odebraly kontakty, která stále roste, dokud na sobě tělesa leží. Metoda, která sleduje volný pád přesně, například rychlostní Verletova metoda, proto i&#xa0;tak driftuje tam, kde se tělesa dotýkají.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>EditMessages</name>
    <message>
        <source>there is no body number %1</source>
        <translation>těleso číslo %1 neexistuje</translation>
    </message>
    <message>
        <source>the scene holds %1 bodies, the most a scene may have</source>
        <translation>scéna má %1 těles, víc jich mít nemůže</translation>
    </message>
    <message>
        <source>a point is not a number</source>
        <translation>bod není číslo</translation>
    </message>
    <message>
        <source>there is no spring number %1</source>
        <translation>pružina číslo %1 neexistuje</translation>
    </message>
    <message>
        <source>there is no pin number %1</source>
        <translation>čep číslo %1 neexistuje</translation>
    </message>
    <message>
        <source>a pin holds a body: start on a body, then click a second body or empty space for the world</source>
        <translation>čep drží těleso: začněte na tělese, pak klikněte na druhé těleso nebo na prázdné místo pro okolí</translation>
    </message>
    <message>
        <source>the scene holds %1 joints, the most a scene may have</source>
        <translation>scéna má %1 kloubů, víc jich mít nemůže</translation>
    </message>
    <message>
        <source>a spring of zero length: drag from one point to another</source>
        <translation>pružina nulové délky: táhněte od jednoho bodu k&#xa0;druhému</translation>
    </message>
    <message>
        <source>the scene holds %1 springs, the most a scene may have</source>
        <translation>scéna má %1 pružin, víc jich mít nemůže</translation>
    </message>
    <message>
        <source>must be a whole number</source>
        <translation>musí být celé číslo</translation>
    </message>
    <message>
        <source>%1 overlaps %2</source>
        <translation>%1 se překrývá s&#xa0;%2</translation>
    </message>
    <message>
        <source>%1; overlapping bodies are pushed apart when the scene runs</source>
        <translation>%1; překrývající se tělesa se po spuštění scény od sebe odtlačí</translation>
    </message>
    <message>
        <source>must be given</source>
        <translation>musí být zadáno</translation>
    </message>
    <message>
        <source>a shape is drawn, or changed through its sizes</source>
        <translation>tvar se kreslí nebo mění přes své rozměry</translation>
    </message>
    <message>
        <source>not a value this field holds</source>
        <translation>tato vlastnost takovou hodnotu nemá</translation>
    </message>
    <message>
        <source>there is no property &quot;%1&quot;</source>
        <translation>vlastnost „%1“ neexistuje</translation>
    </message>
    <message>
        <source>there is no %1</source>
        <translation>%1 neexistuje</translation>
    </message>
    <message>
        <source>the scene</source>
        <translation>scéna</translation>
    </message>
</context>
<context>
    <name>FileMessages</name>
    <message>
        <source>an array</source>
        <translation>pole</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>objekt</translation>
    </message>
    <message>
        <source>: cannot read: is a directory, not a file</source>
        <translation>: nelze číst: je to složka, ne soubor</translation>
    </message>
    <message>
        <source>: cannot read: </source>
        <translation>: nelze číst: </translation>
    </message>
    <message>
        <source>: too large: more than %1 bytes (the limit is %2 MiB)</source>
        <translation>: příliš velký: víc než %1 bajtů (limit je %2&#xa0;MiB)</translation>
    </message>
    <message>
        <source>unterminated object: a &apos;,&apos; or the closing &apos;}&apos; is missing</source>
        <translation>neukončený objekt: chybí &apos;,&apos; nebo uzavírací &apos;}&apos;</translation>
    </message>
    <message>
        <source>a &apos;:&apos; is missing after a key</source>
        <translation>za klíčem chybí &apos;:&apos;</translation>
    </message>
    <message>
        <source>unterminated array: a &apos;,&apos; or the closing &apos;]&apos; is missing</source>
        <translation>neukončené pole: chybí &apos;,&apos; nebo uzavírací &apos;]&apos;</translation>
    </message>
    <message>
        <source>a &apos;,&apos; is missing between two values</source>
        <translation>mezi dvěma hodnotami chybí &apos;,&apos;</translation>
    </message>
    <message>
        <source>not a JSON value (text needs double quotes; true, false and null are lower case)</source>
        <translation>není hodnota JSON (text patří do dvojitých uvozovek; true, false a&#xa0;null se píší malými písmeny)</translation>
    </message>
    <message>
        <source>the file ends inside a number</source>
        <translation>soubor končí uprostřed čísla</translation>
    </message>
    <message>
        <source>not a valid number</source>
        <translation>neplatné číslo</translation>
    </message>
    <message>
        <source>an invalid escape sequence in a string</source>
        <translation>neplatná escape sekvence v&#xa0;řetězci</translation>
    </message>
    <message>
        <source>the text is not valid UTF-8</source>
        <translation>text není platné UTF-8</translation>
    </message>
    <message>
        <source>unterminated string: the closing &apos;&quot;&apos; is missing</source>
        <translation>neukončený řetězec: chybí uzavírací &apos;&quot;&apos;</translation>
    </message>
    <message>
        <source>a value is missing here (JSON allows no trailing comma)</source>
        <translation>tady chybí hodnota (JSON nedovoluje čárku za poslední položkou)</translation>
    </message>
    <message>
        <source>nested too deeply</source>
        <translation>příliš hluboké vnoření</translation>
    </message>
    <message>
        <source>too large for the JSON reader</source>
        <translation>příliš velké pro čtečku JSON</translation>
    </message>
    <message>
        <source>more text after the end of the JSON document</source>
        <translation>za koncem dokumentu JSON následuje další text</translation>
    </message>
    <message>
        <source>not valid JSON</source>
        <translation>neplatný JSON</translation>
    </message>
    <message>
        <source>from %1 to %2</source>
        <translation>od %1 do %2</translation>
    </message>
    <message>
        <source>: too large: %1 bytes (the limit is %2 MiB)</source>
        <translation>: příliš velký: %1 bajtů (limit je %2&#xa0;MiB)</translation>
    </message>
    <message>
        <source>: line 1, column 1: the file is empty</source>
        <translation>: řádek 1, sloupec 1: soubor je prázdný</translation>
    </message>
    <message>
        <source>%1: line %2, column %3: arrays and objects nested deeper than %4 levels (the limit)</source>
        <translation>%1: řádek %2, sloupec %3: pole a&#xa0;objekty vnořené hlouběji než do %4 úrovní (limit)</translation>
    </message>
    <message>
        <source>number %1 is not a finite double (out of range or malformed)</source>
        <translation>číslo %1 není konečné číslo typu double (je mimo rozsah nebo chybně zapsané)</translation>
    </message>
    <message>
        <source>%1: line %2, column %3: %4</source>
        <translation>%1: řádek %2, sloupec %3: %4</translation>
    </message>
    <message>
        <source>unknown key (allowed here: %1)</source>
        <translation>neznámý klíč (tady jsou povoleny: %1)</translation>
    </message>
    <message>
        <source>must be an object {...}, got </source>
        <translation>musí být objekt {...}, je </translation>
    </message>
    <message>
        <source>missing: %1 starts with &quot;%2&quot;: %3 (the format version)</source>
        <translation>chybí: %1 začíná klíčem &quot;%2&quot;: %3 (verze formátu)</translation>
    </message>
    <message>
        <source>unsupported format version %1 (this RigidLab reads version %2)</source>
        <translation>nepodporovaná verze formátu %1 (tento RigidLab čte verzi %2)</translation>
    </message>
    <message>
        <source>must be an array [...], got </source>
        <translation>musí být pole [...], je </translation>
    </message>
    <message>
        <source>must be a number</source>
        <translation>musí být číslo</translation>
    </message>
    <message>
        <source>must be a positive number</source>
        <translation>musí být kladné číslo</translation>
    </message>
    <message>
        <source>must be a number &gt;= 0</source>
        <translation>musí být číslo &gt;= 0</translation>
    </message>
    <message>
        <source>must be a number from 0 to 1</source>
        <translation>musí být číslo od 0 do 1</translation>
    </message>
    <message>
        <source>, got </source>
        <translation>, je </translation>
    </message>
    <message>
        <source>an array of %1 elements</source>
        <translation>pole s&#xa0;počtem prvků %1</translation>
    </message>
    <message>
        <source>must be a pair of numbers [x, y], got </source>
        <translation>musí být dvojice čísel [x, y], je </translation>
    </message>
    <message>
        <source>required, but missing</source>
        <translation>povinné, ale chybí</translation>
    </message>
    <message>
        <source>must be a whole number from %1 to %2</source>
        <translation>musí být celé číslo od %1 do %2</translation>
    </message>
    <message>
        <source>must be a string &quot;...&quot;, got </source>
        <translation>musí být řetězec &quot;...&quot;, je </translation>
    </message>
    <message>
        <source>must be true or false, got </source>
        <translation>musí být true nebo false, je </translation>
    </message>
    <message>
        <source>must be %1, got %2</source>
        <translation>musí být %1, je %2</translation>
    </message>
    <message>
        <source>must be one line (it is shown in the lesson menu); put longer text in &quot;summary&quot;</source>
        <translation>musí být na jednom řádku (zobrazuje se v&#xa0;nabídce lekcí); delší text patří do &quot;summary&quot;</translation>
    </message>
    <message>
        <source>is %1 characters long; at most %2 fit a menu line (put longer text in &quot;summary&quot;)</source>
        <translation>má %1 znaků; na řádek nabídky se vejde nejvýš %2 (delší text patří do &quot;summary&quot;)</translation>
    </message>
    <message>
        <source>must not be empty (leave the key out instead)</source>
        <translation>nesmí být prázdné (klíč raději vynechte)</translation>
    </message>
    <message>
        <source>a lesson file</source>
        <translation>soubor lekce</translation>
    </message>
    <message>
        <source>must not be empty</source>
        <translation>nesmí být prázdné</translation>
    </message>
    <message>
        <source>must be a non-empty string &quot;...&quot;, got </source>
        <translation>musí být neprázdný řetězec &quot;...&quot;, je </translation>
    </message>
    <message>
        <source>a lesson needs 1 to %1 steps, got %2</source>
        <translation>lekce potřebuje 1 až %1 kroků, má %2</translation>
    </message>
    <message>
        <source>the steps up to this one hold %1 bodies in all, more than the limit of %2 for a lesson</source>
        <translation>kroky až po tento obsahují celkem %1 těles, víc než limit %2 pro lekci</translation>
    </message>
    <message>
        <source>&quot;%1&quot; plots the worlds of &quot;compare&quot;, and this step has none</source>
        <translation>&quot;%1&quot; kreslí světy z&#xa0;&quot;compare&quot;, ale tento krok žádné nemá</translation>
    </message>
    <message>
        <source>must be at most %1 s, got %2</source>
        <translation>musí být nejvýš %1&#xa0;s, je %2</translation>
    </message>
    <message>
        <source>%1 s at a step of %2 s is more than %3 steps</source>
        <translation>%1&#xa0;s při kroku %2&#xa0;s je víc než %3 kroků</translation>
    </message>
    <message>
        <source>the &quot;sat&quot; panel needs the pair it looks at: add &quot;sat&quot;: {&quot;a&quot;: ID, &quot;b&quot;: ID} to the step</source>
        <translation>panel &quot;sat&quot; potřebuje dvojici, kterou zkoumá: přidejte do kroku &quot;sat&quot;: {&quot;a&quot;: ID, &quot;b&quot;: ID}</translation>
    </message>
    <message>
        <source>must be a string or an array of strings, got </source>
        <translation>musí být řetězec nebo pole řetězců, je </translation>
    </message>
    <message>
        <source>required, but missing (a scene object, or the path of a scene file)</source>
        <translation>povinné, ale chybí (objekt scény nebo cesta k&#xa0;souboru scény)</translation>
    </message>
    <message>
        <source>must be a scene object {...} or the path of a scene file, got </source>
        <translation>musí být objekt scény {...} nebo cesta k&#xa0;souboru scény, je </translation>
    </message>
    <message>
        <source>must name a scene file, got an empty path</source>
        <translation>musí uvádět soubor scény, je prázdná cesta</translation>
    </message>
    <message>
        <source>use &apos;/&apos; between folders, got &quot;%1&quot;</source>
        <translation>mezi složkami pište &apos;/&apos;, je &quot;%1&quot;</translation>
    </message>
    <message>
        <source>must be a path relative to the lesson&apos;s folder, got &quot;%1&quot;</source>
        <translation>musí být cesta relativní ke složce lekce, je &quot;%1&quot;</translation>
    </message>
    <message>
        <source>must not hold control characters</source>
        <translation>nesmí obsahovat řídicí znaky</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a plain file</source>
        <translation>&quot;%1&quot; není obyčejný soubor</translation>
    </message>
    <message>
        <source>unknown integrator &quot;%1&quot; (expected %2)</source>
        <translation>neznámý integrátor &quot;%1&quot; (očekáváno: %2)</translation>
    </message>
    <message>
        <source>unknown solver &quot;%1&quot; (expected %2)</source>
        <translation>neznámý řešič &quot;%1&quot; (očekáváno: %2)</translation>
    </message>
    <message>
        <source>compare &quot;integrators&quot; or &quot;solvers&quot;, not both</source>
        <translation>porovnávejte &quot;integrators&quot;, nebo &quot;solvers&quot;, ne obojí</translation>
    </message>
    <message>
        <source>needs &quot;integrators&quot; or &quot;solvers&quot;: the worlds to run side by side</source>
        <translation>potřebuje &quot;integrators&quot; nebo &quot;solvers&quot;: světy, které poběží vedle sebe</translation>
    </message>
    <message>
        <source>settings.%1 is given too: the main world runs the first of this list, so leave settings.%1 out</source>
        <translation>zadáno je i&#xa0;settings.%1: hlavní svět běží s&#xa0;první položkou tohoto seznamu, settings.%1 proto vynechte</translation>
    </message>
    <message>
        <source>compares 2 to %1 worlds, got %2</source>
        <translation>porovnává 2 až %1 světů, je jich %2</translation>
    </message>
    <message>
        <source>must be a name &quot;...&quot;, got </source>
        <translation>musí být název &quot;...&quot;, je </translation>
    </message>
    <message>
        <source>&quot;%1&quot; is listed twice</source>
        <translation>&quot;%1&quot; je uvedeno dvakrát</translation>
    </message>
    <message>
        <source>unknown %1 &quot;%2&quot; (expected %3)</source>
        <translation>%1 &quot;%2&quot; neexistuje (očekáváno: %3)</translation>
    </message>
    <message>
        <source>: the top level must be an object {...}, got an array</source>
        <translation>: nejvyšší úroveň musí být objekt {...}, je pole</translation>
    </message>
    <message>
        <source>no body with id &quot;%1&quot;</source>
        <translation>žádné těleso nemá id &quot;%1&quot;</translation>
    </message>
    <message>
        <source>unknown measure &quot;%1&quot; (expected %2)</source>
        <translation>neznámé měření &quot;%1&quot; (očekáváno: %2)</translation>
    </message>
    <message>
        <source>body &quot;%1&quot; is static: it never moves</source>
        <translation>těleso &quot;%1&quot; je statické: nikdy se nepohne</translation>
    </message>
    <message>
        <source>body &quot;%1&quot; is kinematic: it never bounces</source>
        <translation>těleso &quot;%1&quot; je kinematické: nikdy se neodrazí</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: this step shows no panel &quot;%2&quot; (its panels: %3)</source>
        <translation>&quot;%1&quot;: tento krok nezobrazuje panel &quot;%2&quot; (jeho panely: %3)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: this step shows no plot &quot;%2&quot; (its plots: %3)</source>
        <translation>&quot;%1&quot;: tento krok nezobrazuje graf &quot;%2&quot; (jeho grafy: %3)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a column of the %2 panel, which this step does not show</source>
        <translation>&quot;%1&quot; je sloupec panelu %2, který tento krok nezobrazuje</translation>
    </message>
    <message>
        <source>unknown name &quot;%1&quot; (expected run, panel:NAME, plot:NAME, %2, %3)</source>
        <translation>neznámý název &quot;%1&quot; (očekáváno: run, panel:NAME, plot:NAME, %2, %3)</translation>
    </message>
    <message>
        <source>required, but missing (what the answer is checked against)</source>
        <translation>povinné, ale chybí (s&#xa0;čím se odpověď porovnává)</translation>
    </message>
    <message>
        <source>0, and so is absoluteTolerance: no typed answer would ever be right</source>
        <translation>0, stejně jako absoluteTolerance: žádná zadaná odpověď by nikdy nebyla správná</translation>
    </message>
    <message>
        <source>the same body as &quot;a&quot;: the test needs two bodies</source>
        <translation>totéž těleso jako &quot;a&quot;: test potřebuje dvě tělesa</translation>
    </message>
    <message>
        <source>body &quot;%1&quot; is a circle: the separating axis test steps through polygons (boxes and polygons)</source>
        <translation>těleso &quot;%1&quot; je kruh: test oddělující osy prochází mnohoúhelníky (obdélníky a&#xa0;mnohoúhelníky)</translation>
    </message>
    <message>
        <source>%1 questions, more than the limit of %2</source>
        <translation>počet otázek %1 překračuje limit %2</translation>
    </message>
    <message>
        <source>a scene file</source>
        <translation>soubor scény</translation>
    </message>
    <message>
        <source>required, but missing (it may be empty: [])</source>
        <translation>povinné, ale chybí (smí být prázdné: [])</translation>
    </message>
    <message>
        <source>%1 bodies, more than the limit of %2</source>
        <translation>počet těles %1 překračuje limit %2</translation>
    </message>
    <message>
        <source>longer than %1 characters</source>
        <translation>delší než %1 znaků</translation>
    </message>
    <message>
        <source>must not be empty (leave &quot;label&quot; out to show the id)</source>
        <translation>nesmí být prázdný (bez klíče &quot;label&quot; se ukáže id)</translation>
    </message>
    <message>
        <source>duplicate id &quot;%1&quot; (bodies[%2] has it already)</source>
        <translation>opakované id &quot;%1&quot; (už ho má bodies[%2])</translation>
    </message>
    <message>
        <source>unknown body type &quot;%1&quot; (expected dynamic, static, kinematic)</source>
        <translation>neznámý typ tělesa &quot;%1&quot; (očekáváno: dynamic, static, kinematic)</translation>
    </message>
    <message>
        <source>give &quot;density&quot; or &quot;mass&quot;, not both</source>
        <translation>zadejte &quot;density&quot;, nebo &quot;mass&quot;, ne obojí</translation>
    </message>
    <message>
        <source>too large or too small: its area works out as %1 m^2</source>
        <translation>příliš velký nebo příliš malý: obsah vychází %1&#xa0;m^2</translation>
    </message>
    <message>
        <source>the mass works out as %1 kg (density times area); it must be %2</source>
        <translation>hmotnost vychází %1&#xa0;kg (hustota krát obsah); musí být %2</translation>
    </message>
    <message>
        <source>a static body never moves: its velocity is ignored (make it &quot;kinematic&quot; to move it)</source>
        <translation>statické těleso se nikdy nepohne: jeho rychlost se nepoužije (má-li se pohybovat, zadejte &quot;kinematic&quot;)</translation>
    </message>
    <message>
        <source>a polygon needs 3 to %1 vertices, got %2</source>
        <translation>mnohoúhelník potřebuje 3 až %1 vrcholů, má %2</translation>
    </message>
    <message>
        <source>unknown shape type &quot;%1&quot; (expected circle, box, polygon)</source>
        <translation>neznámý typ tvaru &quot;%1&quot; (očekáváno: circle, box, polygon)</translation>
    </message>
    <message>
        <source>required, but missing (a body id)</source>
        <translation>povinné, ale chybí (id tělesa)</translation>
    </message>
    <message>
        <source>must be a body id, not null</source>
        <translation>musí být id tělesa, ne null</translation>
    </message>
    <message>
        <source>must be a body id (a string)%1, got %2</source>
        <translation>musí být id tělesa (řetězec)%1, je %2</translation>
    </message>
    <message>
        <source> or null</source>
        <translation> nebo null</translation>
    </message>
    <message>
        <source>%1 springs, more than the limit of %2</source>
        <translation>počet pružin %1 překračuje limit %2</translation>
    </message>
    <message>
        <source>both ends are fixed in the world (a and b are null): a spring needs a body at one end</source>
        <translation>oba konce jsou pevně ve světě (&quot;a&quot; i&#xa0;&quot;b&quot; jsou null): pružina potřebuje těleso aspoň na jednom konci</translation>
    </message>
    <message>
        <source>the same body as &quot;a&quot;: a spring joins two bodies</source>
        <translation>totéž těleso jako &quot;a&quot;: pružina spojuje dvě tělesa</translation>
    </message>
    <message>
        <source>the anchors are too far apart to measure</source>
        <translation>kotevní body jsou od sebe příliš daleko, vzdálenost nelze změřit</translation>
    </message>
    <message>
        <source>%1 joints, more than the limit of %2</source>
        <translation>počet kloubů %1 překračuje limit %2</translation>
    </message>
    <message>
        <source>unknown joint type &quot;%1&quot; (expected pin)</source>
        <translation>neznámý typ kloubu &quot;%1&quot; (očekáváno: pin)</translation>
    </message>
    <message>
        <source>the same body as &quot;a&quot;: a pin joins two bodies</source>
        <translation>totéž těleso jako &quot;a&quot;: čep spojuje dvě tělesa</translation>
    </message>
    <message>
        <source>the anchors are %1 m apart at the start; the joint pulls them together at once</source>
        <translation>kotevní body jsou na začátku %1&#xa0;m od sebe; kloub je hned stáhne k&#xa0;sobě</translation>
    </message>
    <message>
        <source>unknown language &quot;%1&quot; (expected %2)</source>
        <translation>neznámý jazyk &quot;%1&quot; (očekáváno: %2)</translation>
    </message>
    <message>
        <source>must be %1, or an object of languages {&quot;en&quot;: ..., &quot;cs&quot;: ...}, got </source>
        <translation>musí být %1 nebo objekt jazyků {&quot;en&quot;: ..., &quot;cs&quot;: ...}, je </translation>
    </message>
    <message>
        <source>must be a string &quot;...&quot;, or an object of languages {&quot;en&quot;: &quot;...&quot;, &quot;cs&quot;: &quot;...&quot;}, got </source>
        <translation>musí být řetězec &quot;...&quot; nebo objekt jazyků {&quot;en&quot;: &quot;...&quot;, &quot;cs&quot;: &quot;...&quot;}, je </translation>
    </message>
    <message>
        <source>%1 %2, more than the limit of %3</source>
        <translation>%2: počet položek %1 překračuje limit %3</translation>
    </message>
    <message>
        <source>must be an array [...], or an object of languages {&quot;en&quot;: [...], &quot;cs&quot;: [...]}, got </source>
        <translation>musí být pole [...] nebo objekt jazyků {&quot;en&quot;: [...], &quot;cs&quot;: [...]}, je </translation>
    </message>
    <message>
        <source>the lesson&apos;s folder</source>
        <translation>složku lekce</translation>
    </message>
    <message>
        <source>the data folder (scenes/ and lessons/)</source>
        <translation>datovou složku (scenes/ a&#xa0;lessons/)</translation>
    </message>
    <message>
        <source>must not leave %1, got &quot;%2&quot;</source>
        <translation>nesmí vést mimo %1, je &quot;%2&quot;</translation>
    </message>
    <message>
        <source>&quot;%1&quot; leads out of %2 (through a symbolic link)</source>
        <translation>&quot;%1&quot; vede mimo %2 (přes symbolický odkaz)</translation>
    </message>
    <message>
        <source>must be a colour &quot;#rrggbb&quot; (six hexadecimal digits, as &quot;#d04030&quot;), got &quot;%1&quot;</source>
        <translation>musí být barva &quot;#rrggbb&quot; (šest šestnáctkových číslic, např. &quot;#d04030&quot;), je &quot;%1&quot;</translation>
    </message>
    <message>
        <source>must be one line</source>
        <translation>musí být na jednom řádku</translation>
    </message>
    <message>
        <source>more than %1 entries</source>
        <translation>víc než %1 položek</translation>
    </message>
    <message>
        <source>must be from -%1 to %1, got %2</source>
        <translation>musí být od -%1 do %1, je %2</translation>
    </message>
    <message>
        <source>an answers file</source>
        <translation>soubor odpovědí</translation>
    </message>
    <message>
        <source>must be a date YYYY-MM-DD, got &quot;%1&quot;</source>
        <translation>musí být datum RRRR-MM-DD, je „%1“</translation>
    </message>
    <message>
        <source>must be a JSON object {...}</source>
        <translation>musí být objekt JSON {...}</translation>
    </message>
    <message>
        <source>steps: %1 steps, the lesson has %2</source>
        <translation>steps: %1 kroků, lekce jich má %2</translation>
    </message>
    <message>
        <source>steps[%1].questions: %2 questions, the lesson&apos;s step %3 has %4</source>
        <translation>steps[%1].questions: %2 otázek, krok %3 lekce jich má %4</translation>
    </message>
    <message>
        <source>must be one line of at most %1 characters</source>
        <translation>musí být jeden řádek o nejvýše %1 znacích</translation>
    </message>
    <message>
        <source>must be a date written YYYY-MM-DD, got &quot;%1&quot;</source>
        <translation>musí být datum ve tvaru RRRR-MM-DD, je „%1“</translation>
    </message>
    <message>
        <source>holds %1 scenes; a lesson file holds at most %2</source>
        <translation>obsahuje %1 scén; soubor lekce jich obsahuje nejvýše %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a scene&apos;s name in a lesson file (scenes/NAME.json, NAME of letters, digits, _ . -)</source>
        <translation>„%1“ není název scény v souboru lekce (scenes/NÁZEV.json, NÁZEV z písmen, číslic, _ . -)</translation>
    </message>
    <message>
        <source>a lesson file (.rlesson)</source>
        <translation>soubor lekce (.rlesson)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not among the scenes this file holds (%2)</source>
        <translation>„%1“ není mezi scénami, které tento soubor obsahuje (%2)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žádné</translation>
    </message>
    <message>
        <source>sets nothing (leave the key out when the student sets nothing)</source>
        <translation>nic nenastavuje (když žák nic nenastavuje, klíč vynechte)</translation>
    </message>
    <message>
        <source>slow motion does not change what is measured: leave it out</source>
        <translation>zpomalení nemění, co se měří: vynechte ho</translation>
    </message>
    <message>
        <source>this step compares integrators, each world its own: the student cannot choose one</source>
        <translation>tento krok porovnává integrátory, každý svět má svůj: žák žádný vybrat nemůže</translation>
    </message>
    <message>
        <source>this step compares solvers, each world its own: the student cannot choose one</source>
        <translation>tento krok porovnává řešiče, každý svět má svůj: žák žádný vybrat nemůže</translation>
    </message>
    <message>
        <source>the student is asked to set %1, but this step locks it (&quot;allow&quot; does not list it)</source>
        <translation>žák má nastavit %1, ale tento krok to zamyká (&quot;allow&quot; to neuvádí)</translation>
    </message>
    <message>
        <source>the student is asked to set %1 with the controls, but this step does not show the controls panel</source>
        <translation>žák má ovládáním nastavit %1, ale tento krok panel Ovládání nezobrazuje</translation>
    </message>
    <message>
        <source>the student is asked to set %1 with the controls, which this question holds back until it is answered</source>
        <translation>žák má ovládáním nastavit %1, ale tato otázka Ovládání zadržuje, dokud není zodpovězena</translation>
    </message>
    <message>
        <source>not with &quot;choice&quot;: a try either chooses an option or gives a number</source>
        <translation>nepatří k &quot;choice&quot;: pokus buď volí možnost, nebo udává číslo</translation>
    </message>
    <message>
        <source>must be the option&apos;s text, 1 to %1 characters</source>
        <translation>musí být text možnosti, 1 až %1 znaků</translation>
    </message>
    <message>
        <source>only with &quot;choice&quot; (the option chosen)</source>
        <translation>jen spolu s &quot;choice&quot; (zvolenou možností)</translation>
    </message>
    <message>
        <source>required with &quot;answer&quot;, but missing (the options to choose from)</source>
        <translation>povinné spolu s &quot;answer&quot;, ale chybí (možnosti, ze kterých se volí)</translation>
    </message>
    <message>
        <source>must be an array of %1 to %2 options, each a text &quot;...&quot; or {&quot;en&quot;: &quot;...&quot;, &quot;cs&quot;: &quot;...&quot;}, got </source>
        <translation>musí být pole %1 až %2 možností, každá text &quot;...&quot; nebo {&quot;en&quot;: &quot;...&quot;, &quot;cs&quot;: &quot;...&quot;}, je </translation>
    </message>
    <message>
        <source>options</source>
        <translation>možnosti</translation>
    </message>
    <message>
        <source>%1 options, fewer than the %2 a choice needs</source>
        <translation>počet možností %1 je menší než %2, kolik otázka s výběrem potřebuje</translation>
    </message>
    <message>
        <source>required, but missing (the index of the right option, 0 for the first)</source>
        <translation>povinné, ale chybí (pořadí správné možnosti, 0 pro první)</translation>
    </message>
    <message>
        <source>no %1 text (&quot;%2&quot;) in the whole lesson: it will show in %3</source>
        <translation>v celé lekci chybí text v jazyce %1 (&quot;%2&quot;): zobrazí se v jazyce %3</translation>
    </message>
    <message>
        <source>unknown key</source>
        <translation>neznámý klíč</translation>
    </message>
    <message>
        <source>the run stops at %1 s, before questions[%2] measures at %3 s</source>
        <translation>běh se zastaví v čase %1&#xa0;s, dřív než questions[%2] měří v čase %3&#xa0;s</translation>
    </message>
    <message>
        <source>needs a text in at least one language (%1)</source>
        <translation>potřebuje text aspoň v jednom jazyce (%1)</translation>
    </message>
    <message>
        <source>no %1 text (&quot;%2&quot;): it will show in %3</source>
        <translation>chybí text v jazyce %1 (&quot;%2&quot;): zobrazí se v jazyce %3</translation>
    </message>
    <message>
        <source>no %1 text (&quot;%2&quot;) in the whole scene: it will show in %3</source>
        <translation>v celé scéně chybí text v jazyce %1 (&quot;%2&quot;): zobrazí se v jazyce %3</translation>
    </message>
    <message>
        <source>lesson: answers to &quot;%1&quot;, not to &quot;%2&quot;</source>
        <translation>lesson: odpovědi k „%1“, ne k „%2“</translation>
    </message>
    <message>
        <source>: bodies: more than %1 pairs of bodies overlap or nearly touch (around &quot;%2&quot; at %3, %4 m): so crowded a start needs memory and time growing with the square of the bodies; spread them out</source>
        <translation>: bodies: víc než %1 dvojic těles se překrývá nebo téměř dotýká (kolem „%2“ v %3, %4 m): tak nahuštěný začátek potřebuje paměť a čas rostoucí se čtvercem počtu těles; rozmístěte je</translation>
    </message>
    <message>
        <source>: bodies: %1 or more pairs of bodies start overlapping (&quot;%2&quot; and &quot;%3&quot; among them): the contacts push them apart at once</source>
        <translation>: bodies: %1 nebo víc dvojic těles se na začátku překrývá (mezi nimi „%2“ a „%3“): kontakty je hned odtlačí od sebe</translation>
    </message>
    <message>
        <source>not for a question with &quot;%1&quot;: %2</source>
        <translation>nepatří k otázce s &quot;%1&quot;: %2</translation>
    </message>
    <message>
        <source>it is answered by choosing, nothing is measured</source>
        <translation>odpovídá se na ni výběrem, nic se neměří</translation>
    </message>
    <message>
        <source>its answer is the number the lesson gives, nothing is measured or chosen</source>
        <translation>její odpovědí je číslo, které uvádí lekce, nic se neměří ani nevybírá</translation>
    </message>
</context>
<context>
    <name>ImpulseFormula</name>
    <message>
        <source>(%1, %2)</source>
        <translation>(%1; %2)</translation>
    </message>
    <message>
        <source>The impulse of this collision, term by term (A: %1, B: %2)</source>
        <translation>Impuls této srážky člen po členu (A: %1, B: %2)</translation>
    </message>
    <message>
        <source>e = %1: the coefficient of restitution</source>
        <translation>e = %1: koeficient restituce</translation>
    </message>
    <message>
        <source>n = %1: the contact normal, from B to A</source>
        <translation>n = %1: normála kontaktu, od B k&#xa0;A</translation>
    </message>
    <message>
        <source>(v&lt;sub&gt;A&lt;/sub&gt; − v&lt;sub&gt;B&lt;/sub&gt;)·n = %1: how fast the contact points approach along n (negative: approaching)</source>
        <translation>(v&lt;sub&gt;A&lt;/sub&gt; − v&lt;sub&gt;B&lt;/sub&gt;)·n = %1: jak rychle se body dotyku přibližují podél n (záporná: přibližují se)</translation>
    </message>
    <message>
        <source>1/m&lt;sub&gt;A&lt;/sub&gt; = %1, 1/m&lt;sub&gt;B&lt;/sub&gt; = %2: the masses (0 for a body that does not move)</source>
        <translation>1/m&lt;sub&gt;A&lt;/sub&gt; = %1, 1/m&lt;sub&gt;B&lt;/sub&gt; = %2: hmotnosti (0 pro těleso, které se nehýbe)</translation>
    </message>
    <message>
        <source>r&lt;sub&gt;A&lt;/sub&gt; = %1: the lever arm of A, from its centre of mass to the contact point; (r&lt;sub&gt;A&lt;/sub&gt; × n)²/I&lt;sub&gt;A&lt;/sub&gt; = %2</source>
        <translation>r&lt;sub&gt;A&lt;/sub&gt; = %1: rameno tělesa A, od jeho těžiště k&#xa0;bodu dotyku; (r&lt;sub&gt;A&lt;/sub&gt; × n)²/I&lt;sub&gt;A&lt;/sub&gt; = %2</translation>
    </message>
    <message>
        <source>r&lt;sub&gt;B&lt;/sub&gt; = %1: the lever arm of B; (r&lt;sub&gt;B&lt;/sub&gt; × n)²/I&lt;sub&gt;B&lt;/sub&gt; = %2</source>
        <translation>r&lt;sub&gt;B&lt;/sub&gt; = %1: rameno tělesa B; (r&lt;sub&gt;B&lt;/sub&gt; × n)²/I&lt;sub&gt;B&lt;/sub&gt; = %2</translation>
    </message>
    <message>
        <source>j is shown once you have answered the lesson&apos;s question.</source>
        <translation>j se ukáže, jakmile odpovíte na otázku lekce.</translation>
    </message>
</context>
<context>
    <name>Judge</name>
    <message>
        <source>Run the simulation until t = %1 s first.</source>
        <translation>Nejdřív nechte simulaci běžet až do t = %1&#xa0;s.</translation>
    </message>
    <message>
        <source>Type a number first.</source>
        <translation>Nejdřív zadejte číslo.</translation>
    </message>
    <message>
        <source>Not quite (you said %1). Try once more.</source>
        <translation>Ne tak docela (vaše odpověď: %1). Zkuste to ještě jednou.</translation>
    </message>
    <message>
        <source>Not quite (you said %1). Hint: %2</source>
        <translation>Ne tak docela (vaše odpověď: %1). Nápověda: %2</translation>
    </message>
    <message>
        <source>Right: the simulation measured %1 (you said %2).</source>
        <translation>Správně: simulace naměřila %1 (vaše odpověď: %2).</translation>
    </message>
    <message>
        <source>Not quite: the simulation measured %1 (you said %2).</source>
        <translation>Ne tak docela: simulace naměřila %1 (vaše odpověď: %2).</translation>
    </message>
    <message>
        <source>The simulation measured %1.</source>
        <translation>Simulace naměřila %1.</translation>
    </message>
    <message>
        <source>Run the simulation past the top of the first bounce first.</source>
        <translation>Nejdřív nechte simulaci běžet až za vrchol prvního odskoku.</translation>
    </message>
    <message>
        <source>Run the simulation past the top of the second bounce first.</source>
        <translation>Nejdřív nechte simulaci běžet až za vrchol druhého odskoku.</translation>
    </message>
    <message>
        <source>Run the simulation past the top of the third bounce first.</source>
        <translation>Nejdřív nechte simulaci běžet až za vrchol třetího odskoku.</translation>
    </message>
    <message>
        <source>Run the simulation past the top of bounce number %1 first.</source>
        <translation>Nejdřív nechte simulaci běžet až za vrchol odskoku číslo %1.</translation>
    </message>
    <message>
        <source>Right: when it runs, the simulation will measure %1 (you said %2).</source>
        <translation>Správně: až simulace poběží, naměří %1 (vaše odpověď: %2).</translation>
    </message>
    <message>
        <source>Not quite: when it runs, the simulation will measure %1 (you said %2).</source>
        <translation>Ne tak docela: až simulace poběží, naměří %1 (vaše odpověď: %2).</translation>
    </message>
    <message>
        <source>When it runs, the simulation will measure %1.</source>
        <translation>Až simulace poběží, naměří %1.</translation>
    </message>
    <message>
        <source>The right answer: “%1”.</source>
        <translation>Správná odpověď: „%1“.</translation>
    </message>
    <message>
        <source>Not quite (you chose “%1”). Try once more.</source>
        <translation>Ne tak docela (vaše volba: „%1“). Zkuste to ještě jednou.</translation>
    </message>
    <message>
        <source>Not quite (you chose “%1”). Hint: %2</source>
        <translation>Ne tak docela (vaše volba: „%1“). Nápověda: %2</translation>
    </message>
    <message>
        <source>Right: “%1”.</source>
        <translation>Správně: „%1“.</translation>
    </message>
    <message>
        <source>Not quite: the right answer is “%1” (you chose “%2”).</source>
        <translation>Ne tak docela: správná odpověď je „%1“ (vaše volba: „%2“).</translation>
    </message>
    <message>
        <source>The right answer is %1.</source>
        <translation>Správný výsledek je %1.</translation>
    </message>
    <message>
        <source>Right: the answer is %1 (you said %2).</source>
        <translation>Správně: výsledek je %1 (vaše odpověď: %2).</translation>
    </message>
    <message>
        <source>Not quite: the right answer is %1 (you said %2).</source>
        <translation>Ne tak docela: správný výsledek je %1 (vaše odpověď: %2).</translation>
    </message>
</context>
<context>
    <name>LessonExport</name>
    <message>
        <source>by solver</source>
        <translation>podle řešiče</translation>
    </message>
    <message>
        <source>by integrator</source>
        <translation>podle integrátoru</translation>
    </message>
    <message>
        <source>Total energy %1</source>
        <translation>Celková energie %1</translation>
    </message>
    <message>
        <source>energy E</source>
        <translation>energie E</translation>
    </message>
    <message>
        <source>Energy drift %1</source>
        <translation>Energetický drift %1</translation>
    </message>
    <message>
        <source>drift</source>
        <translation>drift</translation>
    </message>
    <message>
        <source>%1, step %2: %3</source>
        <translation>%1, krok %2: %3</translation>
    </message>
    <message>
        <source>integrators %1</source>
        <translation>integrátory %1</translation>
    </message>
    <message>
        <source>integrator %1</source>
        <translation>integrátor %1</translation>
    </message>
    <message>
        <source> · solvers %1</source>
        <translation> · řešiče %1</translation>
    </message>
    <message>
        <source> · dt = %1 s</source>
        <translation> · dt = %1&#xa0;s</translation>
    </message>
    <message>
        <source>cannot make the folder %1</source>
        <translation>nelze vytvořit složku %1</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Settings not saved: cannot write %1</source>
        <translation>Nastavení se neuložilo: nelze zapisovat do %1</translation>
    </message>
</context>
<context>
    <name>MeasuredQuestion</name>
    <message>
        <source>height of a bounce&apos;s top</source>
        <translation>výška vrcholu odskoku</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>rychlost</translation>
    </message>
    <message>
        <source>velocity x</source>
        <translation>rychlost x</translation>
    </message>
    <message>
        <source>velocity y</source>
        <translation>rychlost y</translation>
    </message>
    <message>
        <source>angular velocity</source>
        <translation>úhlová rychlost</translation>
    </message>
    <message>
        <source>position x</source>
        <translation>poloha x</translation>
    </message>
    <message>
        <source>position y</source>
        <translation>poloha y</translation>
    </message>
    <message>
        <source>energy drift</source>
        <translation>energetický drift</translation>
    </message>
    <message>
        <source>momentum x</source>
        <translation>hybnost x</translation>
    </message>
    <message>
        <source>momentum y</source>
        <translation>hybnost y</translation>
    </message>
    <message>
        <source>How high does %1 rise after its bounce %2?</source>
        <translation>Jak vysoko vystoupí %1 po %2. odrazu?</translation>
    </message>
    <message>
        <source>What is the %1 at t = %2&#xa0;s?</source>
        <translation>Jaká je veličina „%1“ v&#xa0;čase t = %2&#xa0;s?</translation>
    </message>
    <message>
        <source>What is the %1 of %2 at t = %3&#xa0;s?</source>
        <translation>Jaká je veličina „%1“ tělesa %2 v&#xa0;čase t = %3&#xa0;s?</translation>
    </message>
    <message>
        <source>Your prediction (%1):</source>
        <translation>Vaše předpověď (%1):</translation>
    </message>
    <message>
        <source>Measured (%1):</source>
        <translation>Naměřeno (%1):</translation>
    </message>
    <message>
        <source>Not measured within the step&apos;s run.</source>
        <translation>V&#xa0;běhu kroku se nic nezměřilo.</translation>
    </message>
    <message>
        <source>Measured: %1 (accepted from %2 to %3)</source>
        <translation>Naměřeno: %1 (uznává se od %2 do %3)</translation>
    </message>
    <message>
        <source>Measured value: %1</source>
        <translation>Naměřená hodnota: %1</translation>
    </message>
    <message>
        <source>a number measured from the run</source>
        <translation>číslo změřené v simulaci</translation>
    </message>
    <message>
        <source>The answer the lab measures</source>
        <translation>Odpověď, kterou laboratoř naměří</translation>
    </message>
    <message>
        <source>⚠ The run does not get there (or diverges first): raise the step&apos;s export time or choose an earlier time.</source>
        <translation>⚠ Simulace tam nedoběhne (nebo se dřív rozběhne): prodlužte čas exportu kroku nebo zvolte dřívější čas.</translation>
    </message>
    <message>
        <source>The lab measures %1 %3; answers from %2 to %4 %3 are right.</source>
        <translation>Laboratoř naměří %1&#xa0;%3; správně jsou odpovědi od %2 do %4&#xa0;%3.</translation>
    </message>
    <message>
        <source>What is measured</source>
        <translation>Co se měří</translation>
    </message>
    <message>
        <source>Body measured</source>
        <translation>Měřené těleso</translation>
    </message>
    <message>
        <source>Time of the measurement</source>
        <translation>Čas měření</translation>
    </message>
    <message>
        <source>Unit of the answer</source>
        <translation>Jednotka odpovědi</translation>
    </message>
    <message>
        <source>Tolerance of the answer</source>
        <translation>Tolerance odpovědi</translation>
    </message>
    <message>
        <source>Measu&amp;red</source>
        <translation>Měří &amp;se</translation>
    </message>
    <message>
        <source>&amp;Body</source>
        <translation>&amp;Těleso</translation>
    </message>
    <message>
        <source>&amp;At time</source>
        <translation>&amp;V čase</translation>
    </message>
    <message>
        <source>&amp;Unit</source>
        <translation>&amp;Jednotka</translation>
    </message>
    <message>
        <source>Toleran&amp;ce</source>
        <translation>To&amp;lerance</translation>
    </message>
    <message>
        <source>%1 (not in the scene)</source>
        <translation>%1 (ve scéně není)</translation>
    </message>
</context>
<context>
    <name>NumberGivenQuestion</name>
    <message>
        <source>The right answer</source>
        <translation>Správný výsledek</translation>
    </message>
    <message>
        <source>How far off an answer may be</source>
        <translation>O kolik se odpověď smí lišit</translation>
    </message>
    <message>
        <source>Unit of the answer</source>
        <translation>Jednotka odpovědi</translation>
    </message>
    <message>
        <source>Right ans&amp;wer</source>
        <translation>Správný &amp;výsledek</translation>
    </message>
    <message>
        <source>Right &amp;within ±</source>
        <translation>Správně v &amp;rozmezí ±</translation>
    </message>
    <message>
        <source>&amp;Unit</source>
        <translation>&amp;Jednotka</translation>
    </message>
    <message>
        <source>Give up and show the right answer</source>
        <translation>Vzdát to a ukázat správnou odpověď</translation>
    </message>
    <message>
        <source>Your answer (%1):</source>
        <translation>Vaše odpověď (%1):</translation>
    </message>
    <message>
        <source>Right answer: %1 (accepted from %2 to %3)</source>
        <translation>Správný výsledek: %1 (uznává se od %2 do %3)</translation>
    </message>
    <message>
        <source>Right answer: %1</source>
        <translation>Správný výsledek: %1</translation>
    </message>
    <message>
        <source>a number the lesson gives</source>
        <translation>číslo, které uvádí lekce</translation>
    </message>
    <message>
        <source>The right answer is %1; answers from %2 to %3 are right.</source>
        <translation>Správný výsledek je %1; správně jsou odpovědi od %2 do %3.</translation>
    </message>
</context>
<context>
    <name>OutputMessages</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>nelze zapsat %1: %2</translation>
    </message>
    <message>
        <source>the disk is full (%1)</source>
        <translation>disk je plný (%1)</translation>
    </message>
    <message>
        <source>it is a folder, not a file</source>
        <translation>je to složka, ne soubor</translation>
    </message>
    <message>
        <source>it is neither a file nor a character device or pipe the lab can write to</source>
        <translation>není to soubor ani znakové zařízení nebo roura, do kterých laboratoř umí zapisovat</translation>
    </message>
</context>
<context>
    <name>PlotExportMenu</name>
    <message>
        <source>Exported %1</source>
        <translation>Exportováno: %1</translation>
    </message>
    <message>
        <source>As %1…</source>
        <translation>Jako %1…</translation>
    </message>
    <message>
        <source>No plot is shown</source>
        <translation>Žádný graf není zobrazen</translation>
    </message>
</context>
<context>
    <name>PlotWords</name>
    <message>
        <source>%1, from %2 to %3</source>
        <translation>%1, od %2 do %3</translation>
    </message>
    <message>
        <source>%1: no values yet</source>
        <translation>%1: zatím bez hodnot</translation>
    </message>
    <message>
        <source>%1: now %2, least %3, greatest %4</source>
        <translation>%1: nyní %2, nejméně %3, nejvíce %4</translation>
    </message>
    <message>
        <source>Plot %1.</source>
        <translation>Graf %1.</translation>
    </message>
    <message>
        <source>Horizontal axis: %1.</source>
        <translation>Vodorovná osa: %1.</translation>
    </message>
    <message>
        <source>Vertical axis: %1.</source>
        <translation>Svislá osa: %1.</translation>
    </message>
    <message>
        <source>Right axis: %1.</source>
        <translation>Pravá osa: %1.</translation>
    </message>
</context>
<context>
    <name>QAbstractFileIconProvider</name>
    <message>
        <source>Folder</source>
        <comment>All other platforms</comment>
        <translation>Složka</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <comment>All other platforms</comment>
        <translation>Zástupce</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Jednotka</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Neznámý</translation>
    </message>
</context>
<context>
    <name>SatHandout</name>
    <message>
        <source>The test stops at axis %1 of the %2 it tried: a gap, so no collision.</source>
        <translation>Test se zastaví u&#xa0;osy %1 z&#xa0;%2 vyzkoušených: mezera, tedy žádná srážka.</translation>
    </message>
    <message>
        <source>All %1 axes overlap: the polygons intersect. Least penetration: axis %2, depth %3.</source>
        <translation>Všech %1 os se překrývá: mnohoúhelníky se protínají. Nejmenší průnik: osa %2, hloubka %3.</translation>
    </message>
    <message>
        <source>%1. normal of %2, edge %3
n = (%4, %5)</source>
        <translation>%1. normála tělesa %2, hrana %3
n = (%4; %5)</translation>
    </message>
    <message>
        <source>gap %1</source>
        <translation>mezera %1</translation>
    </message>
    <message>
        <source>overlap %1</source>
        <translation>překryv %1</translation>
    </message>
    <message>
        <source>separating axis</source>
        <translation>oddělující osa</translation>
    </message>
    <message>
        <source>least penetration</source>
        <translation>nejmenší průnik</translation>
    </message>
    <message>
        <source>A [%1, %2]</source>
        <translation>A [%1; %2]</translation>
    </message>
    <message>
        <source>B [%1, %2]</source>
        <translation>B [%1; %2]</translation>
    </message>
    <message>
        <source>Separating axis test: %1 (A) and %2 (B)</source>
        <translation>Test oddělující osy: %1 (A) a&#xa0;%2 (B)</translation>
    </message>
    <message>
        <source>Projections on each axis the test tried, in metres: A filled, B hatched.</source>
        <translation>Průměty na každou osu, kterou test vyzkoušel, v&#xa0;metrech: A plné, B šrafované.</translation>
    </message>
    <message>
        <source>cannot make the folder %1</source>
        <translation>nelze vytvořit složku %1</translation>
    </message>
</context>
<context>
    <name>SatOverlayItem</name>
    <message>
        <source>gap %1 m</source>
        <translation>mezera %1&#xa0;m</translation>
    </message>
    <message>
        <source>overlap %1 m</source>
        <translation>překryv %1&#xa0;m</translation>
    </message>
    <message>
        <source>separating axis: no collision</source>
        <translation>oddělující osa: žádná srážka</translation>
    </message>
    <message>
        <source>least overlap: this is the contact normal</source>
        <translation>nejmenší překryv: toto je normála kontaktu</translation>
    </message>
    <message>
        <source>least overlap: axis %1, the contact normal (arrow)</source>
        <translation>nejmenší překryv: osa %1, normála kontaktu (šipka)</translation>
    </message>
</context>
<context>
    <name>SceneSchema</name>
    <message>
        <source>Body A</source>
        <translation>Těleso A</translation>
    </message>
    <message>
        <source>Anchor A x</source>
        <translation>Úchyt A x</translation>
    </message>
    <message>
        <source>Anchor A y</source>
        <translation>Úchyt A y</translation>
    </message>
    <message>
        <source>Body B</source>
        <translation>Těleso B</translation>
    </message>
    <message>
        <source>Anchor B x</source>
        <translation>Úchyt B x</translation>
    </message>
    <message>
        <source>Anchor B y</source>
        <translation>Úchyt B y</translation>
    </message>
    <message>
        <source>Stiffness k</source>
        <translation>Tuhost pružiny k</translation>
    </message>
    <message>
        <source>Damping c</source>
        <translation>Tlumení c</translation>
    </message>
    <message>
        <source>Rest length</source>
        <translation>Klidová délka</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrátor</translation>
    </message>
    <message>
        <source>Time step dt</source>
        <translation>Časový krok dt</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Řešič</translation>
    </message>
    <message>
        <source>Iterations</source>
        <translation>Iterace</translation>
    </message>
    <message>
        <source>Restitution e</source>
        <translation>Koeficient restituce e</translation>
    </message>
    <message>
        <source>Friction μ</source>
        <translation>Tření μ</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Tíhová síla</translation>
    </message>
    <message>
        <source>Time scale</source>
        <translation>Časové měřítko</translation>
    </message>
    <message>
        <source>Title</source>
        <translation>Název</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Popis</translation>
    </message>
    <message>
        <source>Gravity gx</source>
        <translation>Tíhové zrychlení gx</translation>
    </message>
    <message>
        <source>Gravity gy</source>
        <translation>Tíhové zrychlení gy</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Gravitation G</source>
        <translation>Gravitační konstanta G</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Odpor prostředí</translation>
    </message>
    <message>
        <source>Sleep</source>
        <translation>Uspávání</translation>
    </message>
    <message>
        <source>Continuous collision</source>
        <translation>Spojitá detekce srážek</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerance</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>Id</translation>
    </message>
    <message>
        <source>Label</source>
        <translation>Popisek</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Tvar</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Šířka</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Výška</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Poloměr</translation>
    </message>
    <message>
        <source>Position x</source>
        <translation>Poloha x</translation>
    </message>
    <message>
        <source>Position y</source>
        <translation>Poloha y</translation>
    </message>
    <message>
        <source>Angle θ</source>
        <translation>Úhel θ</translation>
    </message>
    <message>
        <source>Velocity vx</source>
        <translation>Rychlost vx</translation>
    </message>
    <message>
        <source>Velocity vy</source>
        <translation>Rychlost vy</translation>
    </message>
    <message>
        <source>Angular vel. ω</source>
        <translation>Úhlová rychlost ω</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>Hustota</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>Hmotnost</translation>
    </message>
    <message>
        <source>Collides</source>
        <translation>Srážky</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Barva</translation>
    </message>
    <message>
        <source>dynamic</source>
        <translation>dynamické</translation>
    </message>
    <message>
        <source>static</source>
        <translation>statické</translation>
    </message>
    <message>
        <source>kinematic</source>
        <translation>kinematické</translation>
    </message>
    <message>
        <source>Plots exported at</source>
        <translation>Grafy se exportují v čase</translation>
    </message>
    <message>
        <source>The run stops at</source>
        <translation>Běh se zastaví v čase</translation>
    </message>
    <message>
        <source>Starts at once</source>
        <translation>Spustí se hned</translation>
    </message>
    <message>
        <source>Absolute tolerance</source>
        <translation>Absolutní tolerance</translation>
    </message>
    <message>
        <source>Right answer</source>
        <translation>Správný výsledek</translation>
    </message>
    <message>
        <source>Right within</source>
        <translation>Správně v rozmezí</translation>
    </message>
</context>
<context>
    <name>SceneWords</name>
    <message>
        <source>Scene</source>
        <translation>Scéna</translation>
    </message>
    <message>
        <source>Scene: %1</source>
        <translation>Scéna: %1</translation>
    </message>
    <message numerus="yes">
        <source>On stage: %n moving body(ies)</source>
        <translation>
            <numerusform>Ve scéně: %n pohyblivé těleso</numerusform>
            <numerusform>Ve scéně: %n pohyblivá tělesa</numerusform>
            <numerusform>Ve scéně: %n pohyblivých těles</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n fixed body(ies).</source>
        <translation>
            <numerusform>, %n pevné těleso.</numerusform>
            <numerusform>, %n pevná tělesa.</numerusform>
            <numerusform>, %n pevných těles.</numerusform>
        </translation>
    </message>
    <message>
        <source>The simulation stopped at %1: it diverged.</source>
        <translation>Simulace se zastavila v&#xa0;čase %1: výpočet se rozběhl.</translation>
    </message>
    <message>
        <source>Running, time %1.</source>
        <translation>Běží, čas %1.</translation>
    </message>
    <message>
        <source>Paused at time %1.</source>
        <translation>Pozastaveno v&#xa0;čase %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n pair(s) of bodies touch.</source>
        <translation>
            <numerusform>Dotýká se %n dvojice těles.</numerusform>
            <numerusform>Dotýkají se %n dvojice těles.</numerusform>
            <numerusform>Dotýká se %n dvojic těles.</numerusform>
        </translation>
    </message>
    <message>
        <source>Selected: %1.</source>
        <translation>Vybráno: %1.</translation>
    </message>
    <message>
        <source>%1 runs or pauses; %2 and %3 select a body; arrows move it, Shift+arrows change its velocity, Enter shows its numbers.</source>
        <translation>%1 spustí nebo pozastaví; %2 a&#xa0;%3 vyberou těleso; šipky ho posunou, Shift+šipky změní jeho rychlost, Enter ukáže jeho hodnoty.</translation>
    </message>
    <message>
        <source>circle, radius %1</source>
        <translation>kruh, poloměr %1</translation>
    </message>
    <message>
        <source>box %1 × %2</source>
        <translation>obdélník %1 × %2</translation>
    </message>
    <message numerus="yes">
        <source>polygon, %n corner(s)</source>
        <translation>
            <numerusform>mnohoúhelník, %n vrchol</numerusform>
            <numerusform>mnohoúhelník, %n vrcholy</numerusform>
            <numerusform>mnohoúhelník, %n vrcholů</numerusform>
        </translation>
    </message>
    <message>
        <source>mass %1</source>
        <translation>hmotnost %1</translation>
    </message>
    <message>
        <source>mass infinite</source>
        <translation>hmotnost nekonečná</translation>
    </message>
    <message>
        <source>position %1</source>
        <translation>poloha %1</translation>
    </message>
    <message>
        <source>velocity %1, speed %2</source>
        <translation>rychlost %1, velikost rychlosti %2</translation>
    </message>
    <message>
        <source>touches %1</source>
        <translation>dotýká se: %1</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Shrnutí</translation>
    </message>
    <message>
        <source>What happened</source>
        <translation>Co se stalo</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <comment>a body&apos;s name, then its kind: static, dynamic or kinematic</comment>
        <translation>%1 (%2 těleso)</translation>
    </message>
</context>
<context>
    <name>Screenshots</name>
    <message>
        <source>cannot encode %1 as PNG</source>
        <translation>nelze zakódovat %1 jako PNG</translation>
    </message>
    <message>
        <source>the window needs at least %1×%2 (logical pixels) and was made %3×%4: its content is clipped</source>
        <translation>okno potřebuje alespoň %1×%2 (logických pixelů), ale má %3×%4: jeho obsah je oříznutý</translation>
    </message>
    <message>
        <source>cannot create the folder %1</source>
        <translation>nelze vytvořit složku %1</translation>
    </message>
    <message>
        <source>cannot create a temporary folder for the settings: %1</source>
        <translation>nelze vytvořit dočasnou složku pro nastavení: %1</translation>
    </message>
    <message>
        <source>the welcome scene after %1 s</source>
        <translation>uvítací scéna po %1&#xa0;s</translation>
    </message>
    <message>
        <source>%1, step %2 of %3: %4, after %5 s</source>
        <translation>%1, krok %2 z&#xa0;%3: %4, po %5&#xa0;s</translation>
    </message>
    <message>
        <source>a lesson step with the controls, the inspector and the collision table shown</source>
        <translation>krok lekce s&#xa0;ovládáním, inspektorem a&#xa0;tabulkou srážky</translation>
    </message>
    <message>
        <source>Help › Controls over the window</source>
        <translation>Nápověda › Ovládání nad oknem</translation>
    </message>
    <message>
        <source>the same step in presentation mode</source>
        <translation>týž krok v&#xa0;režimu prezentace</translation>
    </message>
    <message>
        <source>the editor on a new scene</source>
        <translation>editor s&#xa0;novou scénou</translation>
    </message>
    <message>
        <source>a measured drop over the simulated one, the residuals and e fitted to it</source>
        <translation>naměřený pád přes simulovaný, rezidua a&#xa0;e určené z&#xa0;měření</translation>
    </message>
    <message>
        <source>the probe beside the ball hit and a graph of both momenta with their sum</source>
        <translation>sonda u zasažené koule a graf hybností obou koulí s jejich součtem</translation>
    </message>
    <message>
        <source>the ruler between the two balls&apos; starting centres</source>
        <translation>pravítko mezi počátečními středy obou koulí</translation>
    </message>
    <message>
        <source>the lesson editor on a shipped lesson</source>
        <translation>editor lekcí s dodanou lekcí</translation>
    </message>
    <message>
        <source>%1 needs %2×%3 px, more than the %4×%5 asked for</source>
        <translation>%1 potřebuje %2×%3 px, víc než požadovaných %4×%5</translation>
    </message>
    <message>
        <source>cannot create a temporary folder for the class: %1</source>
        <translation>nelze vytvořit dočasnou složku pro třídu: %1</translation>
    </message>
    <message>
        <source>File › Class results… on a class of five, with a damaged file and another lesson&apos;s</source>
        <translation>Soubor › Výsledky třídy… na třídě pěti žáků, s poškozeným souborem a souborem jiné lekce</translation>
    </message>
    <message>
        <source>the window system made the window %1×%2 (logical pixels), not the %3×%4 asked for</source>
        <translation>okenní systém dal oknu velikost %1×%2 (logických pixelů), ne požadovaných %3×%4</translation>
    </message>
</context>
<context>
    <name>SpokenNumbers</name>
    <message>
        <source>minus %1</source>
        <comment>a negative number read aloud</comment>
        <translation>minus %1</translation>
    </message>
</context>
<context>
    <name>StatusWords</name>
    <message>
        <source>–</source>
        <comment>no drift to show</comment>
        <translation>–</translation>
    </message>
</context>
<context>
    <name>Worksheet</name>
    <message>
        <source>… not measured yet</source>
        <translation>… ještě nezměřeno</translation>
    </message>
    <message>
        <source>◆ shown</source>
        <translation>◆ ukázáno</translation>
    </message>
    <message>
        <source>✓ right</source>
        <translation>✓ správně</translation>
    </message>
    <message>
        <source>✗ not right</source>
        <translation>✗ nesprávně</translation>
    </message>
    <message>
        <source>Settings: integrator %1 · dt = %2 s · solver %3</source>
        <translation>Nastavení: integrátor %1 · dt = %2 s · řešič %3</translation>
    </message>
    <message>
        <source>Worksheet</source>
        <translation>Pracovní list</translation>
    </message>
    <message>
        <source>Worksheet to fill in</source>
        <translation>Pracovní list k&#xa0;vyplnění</translation>
    </message>
    <message>
        <source>Teacher&apos;s key: the measured answers</source>
        <translation>Klíč pro učitele: změřené odpovědi</translation>
    </message>
    <message>
        <source>Name: %1</source>
        <translation>Jméno: %1</translation>
    </message>
    <message>
        <source>Class: %1</source>
        <translation>Třída: %1</translation>
    </message>
    <message>
        <source>Date: %1</source>
        <translation>Datum: %1</translation>
    </message>
    <message>
        <source>Step %1: %2</source>
        <translation>Krok %1: %2</translation>
    </message>
    <message>
        <source>Figure %1.%2: %3</source>
        <translation>Obrázek %1.%2: %3</translation>
    </message>
    <message>
        <source>Question %1.%2: %3</source>
        <translation>Otázka %1.%2: %3</translation>
    </message>
    <message>
        <source>Not answered.</source>
        <translation>Bez odpovědi.</translation>
    </message>
    <message>
        <source>Prediction %1</source>
        <translation>Předpověď %1</translation>
    </message>
    <message>
        <source>Answer %1</source>
        <translation>Odpověď %1</translation>
    </message>
    <message>
        <source>Show me</source>
        <translation>Ukaž mi</translation>
    </message>
    <message>
        <source>(no answer)</source>
        <translation>(bez odpovědi)</translation>
    </message>
    <message>
        <source>teacher&apos;s key</source>
        <translation>klíč pro učitele</translation>
    </message>
    <message>
        <source>%1 does not fit the lesson: %2</source>
        <translation>%1 nepatří k&#xa0;lekci: %2</translation>
    </message>
    <message>
        <source>cannot write %1: could not start drawing the PDF</source>
        <translation>nelze zapsat %1: kreslení PDF nešlo začít</translation>
    </message>
    <message>
        <source>on</source>
        <translation>zapnuto</translation>
    </message>
    <message>
        <source>off</source>
        <translation>vypnuto</translation>
    </message>
</context>
<context>
    <name>WorksheetText</name>
    <message>
        <source>page %1</source>
        <translation>strana %1</translation>
    </message>
</context>
<context>
    <name>rigidlab::lessons</name>
    <message>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <source> — %1</source>
        <translation> – %1</translation>
    </message>
    <message>
        <source> (≈%1 min)</source>
        <translation> (≈%1&#xa0;min)</translation>
    </message>
    <message>
        <source> (your own)</source>
        <translation> (vlastní)</translation>
    </message>
    <message>
        <source> (your own: %1)</source>
        <translation> (vlastní: %1)</translation>
    </message>
</context>
<context>
    <name>rigidlab::lessons::Language</name>
    <message>
        <source>English</source>
        <translation>angličtina</translation>
    </message>
    <message>
        <source>Czech</source>
        <translation>čeština</translation>
    </message>
</context>
<context>
    <name>rigidlab::measure</name>
    <message>
        <source>unknown body &quot;%1&quot; (the scene has: %2)</source>
        <translation>neznámé těleso &quot;%1&quot; (scéna má: %2)</translation>
    </message>
    <message>
        <source>the measurement does not depend on %1: it cannot be fitted from it</source>
        <translation>měření na %1 nezávisí: z&#xa0;něj ho nelze určit</translation>
    </message>
    <message>
        <source>the parameters cannot be told apart by this measurement</source>
        <translation>toto měření parametry od sebe neodliší</translation>
    </message>
    <message>
        <source>unknown parameter &quot;%1&quot; (expected restitution, friction, vx or vy)</source>
        <translation>neznámý parametr &quot;%1&quot; (očekáváno: restitution, friction, vx nebo vy)</translation>
    </message>
    <message>
        <source>%1: name one body, as in %2:ball</source>
        <translation>%1: uveďte jedno těleso, např. %2:ball</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: expected QUANTITY:BODY with QUANTITY x, y, vx, vy or v, as in y:ball</source>
        <translation>&quot;%1&quot;: očekáváno VELIČINA:TĚLESO, kde VELIČINA je x, y, vx, vy nebo v, např. y:ball</translation>
    </message>
    <message>
        <source>the measurement lasts %1 s, more than %2 steps of the scene&apos;s %3 s</source>
        <translation>měření trvá %1&#xa0;s, víc než %2 kroků scény po %3&#xa0;s</translation>
    </message>
    <message>
        <source>fit one to three parameters</source>
        <translation>určit lze jeden až tři parametry</translation>
    </message>
    <message>
        <source>%1 points cannot fit %2 parameters: measure more</source>
        <translation>počet bodů (%1) nestačí na počet parametrů (%2): změřte víc</translation>
    </message>
    <message>
        <source>%1 bounce times: e needs at least %2 (three flights between them)</source>
        <translation>časů odrazů je %1: k&#xa0;určení e je potřeba aspoň %2 (tři lety mezi nimi)</translation>
    </message>
    <message>
        <source>bounce %1 is not after bounce %2</source>
        <translation>odraz %1 nenásleduje po odrazu %2</translation>
    </message>
    <message>
        <source>column %1</source>
        <translation>sloupec %1</translation>
    </message>
    <message>
        <source>column %1 (&quot;%2&quot;)</source>
        <translation>sloupec %1 (&quot;%2&quot;)</translation>
    </message>
    <message>
        <source>line %1, %2</source>
        <translation>řádek %1, %2</translation>
    </message>
    <message>
        <source>%1: unknown unit &quot;%2&quot; for %3 (expected %4, or set the unit)</source>
        <translation>%1: neznámá jednotka &quot;%2&quot; pro %3 (očekáváno %4, nebo jednotku nastavte)</translation>
    </message>
    <message>
        <source>%1: the time is missing</source>
        <translation>%1: chybí čas</translation>
    </message>
    <message>
        <source>%1: %2 is too large in the lab&apos;s units</source>
        <translation>%1: %2 je v&#xa0;jednotkách laboratoře příliš velké</translation>
    </message>
    <message>
        <source>%1: the time %2 is not after %3 on line %4 (time must rise from row to row)</source>
        <translation>%1: čas %2 není větší než %3 na řádku %4 (čas musí od řádku k&#xa0;řádku růst)</translation>
    </message>
    <message>
        <source>the mapping names %1 columns, the file has %2</source>
        <translation>přiřazení uvádí sloupců: %1, soubor jich má %2</translation>
    </message>
    <message>
        <source>%1 and %2 both hold %3: map one of them</source>
        <translation>%1 i&#xa0;%2 obsahují %3: přiřaďte jen jeden z&#xa0;nich</translation>
    </message>
    <message>
        <source>no column holds the time (name it t or Time (s), or map a column to it)</source>
        <translation>žádný sloupec neobsahuje čas (pojmenujte ho t nebo Time (s), nebo mu sloupec přiřaďte)</translation>
    </message>
    <message>
        <source>line %1: only one column; a time series needs the time and a measured value (or read it as bounce times)</source>
        <translation>řádek %1: jen jeden sloupec; časová řada potřebuje čas a&#xa0;naměřenou hodnotu (nebo ho načtěte jako časy odrazů)</translation>
    </message>
    <message>
        <source>%1: no numbers from time zero on</source>
        <translation>%1: od nulového času dál žádná čísla</translation>
    </message>
    <message>
        <source>no column holds a measured value (x, y, vx, vy or v)</source>
        <translation>žádný sloupec neobsahuje naměřenou hodnotu (x, y, vx, vy nebo v)</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>řádek %1</translation>
    </message>
    <message>
        <source>line %1, column %2</source>
        <translation>řádek %1, sloupec %2</translation>
    </message>
    <message>
        <source>line %1, column %2 (&quot;%3&quot;)</source>
        <translation>řádek %1, sloupec %2 (&quot;%3&quot;)</translation>
    </message>
    <message>
        <source>%1: binary data (byte %2), not text</source>
        <translation>%1: binární data (bajt %2), ne text</translation>
    </message>
    <message>
        <source>%1: %2 values where the header (or the first row) has %3: a ragged row</source>
        <translation>%1: hodnot je %2, ale záhlaví (nebo první řádek) jich má %3: nerovný řádek</translation>
    </message>
    <message>
        <source>%1: more than %2 rows of numbers (the limit)</source>
        <translation>%1: víc než %2 řádků čísel (limit)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number</source>
        <translation>&quot;%1&quot; není číslo</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a finite number</source>
        <translation>&quot;%1&quot; není konečné číslo</translation>
    </message>
    <message>
        <source>%1: the header names %2 columns, the rows below it have %3</source>
        <translation>%1: záhlaví uvádí sloupců: %2, řádky pod ním jich mají %3</translation>
    </message>
    <message>
        <source>larger than %1 MB (the limit)</source>
        <translation>větší než %1&#xa0;MB (limit)</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>soubor je prázdný</translation>
    </message>
    <message>
        <source>%1: a quote (&quot;) is not closed</source>
        <translation>%1: uvozovka (&quot;) není uzavřená</translation>
    </message>
    <message>
        <source>no row of numbers in the first %1 lines</source>
        <translation>v&#xa0;prvních %1 řádcích není žádný řádek čísel</translation>
    </message>
    <message>
        <source>no row of numbers (a measurement has a number in every column of its rows)</source>
        <translation>žádný řádek čísel (měření má v&#xa0;každém sloupci svých řádků číslo)</translation>
    </message>
    <message>
        <source>%1: %2 columns, more than %3 (the limit)</source>
        <translation>%1: sloupců je %2, víc než %3 (limit)</translation>
    </message>
    <message>
        <source>cannot read: %1</source>
        <translation>nelze číst: %1</translation>
    </message>
    <message>
        <source>%1 bounce times: more than a ball makes (at most %2); is this the time of every frame?</source>
        <translation>%1 časů odrazů: víc, než míček udělá (nejvýš %2); není to čas každého snímku?</translation>
    </message>
    <message>
        <source>the flights between the bounces do not get shorter: not the bounces of one ball (evenly spaced times, such as frames?)</source>
        <translation>lety mezi odrazy se nezkracují: to nejsou odrazy jednoho míčku (rovnoměrně rozložené časy, třeba snímky?)</translation>
    </message>
    <message>
        <source>%1 cannot be determined from these data: values far apart fit them as well (a ball at rest, too few bounces, or too short a measurement)</source>
        <translation>%1 z těchto dat určit nelze: stejně dobře jim odpovídají i hodně vzdálené hodnoty (míček v klidu, příliš málo odrazů nebo příliš krátké měření)</translation>
    </message>
    <message>
        <source>the measurement ends %1 s after the scene starts: fitting it would run %2 steps of %3 s about %4 times; give the file&apos;s time at which the scene starts (--time-zero) or measure a shorter span</source>
        <translation>měření končí %1 s po začátku scény: určení by spustilo %2 kroků po %3 s asi %4krát; zadejte čas v souboru, kdy scéna začíná (--time-zero), nebo změřte kratší úsek</translation>
    </message>
    <message>
        <source>model: the exact flights of a ball bouncing on a flat floor (closed form, no time step)</source>
        <translation>model: přesné lety míčku odrážejícího se od rovné podlahy (vzorcem, bez časového kroku)</translation>
    </message>
    <message>
        <source>%1 by %2</source>
        <translation>%1 o %2</translation>
    </message>
    <message>
        <source>model: the lab&apos;s run at dt = %1 s; halving the step still moved %2: that is added to the interval</source>
        <translation>model: běh laboratoře s dt = %1 s; půlení kroku ještě posunulo %2: to je přičteno k intervalu</translation>
    </message>
    <message>
        <source>model: the lab&apos;s run at dt = %1 s (halving the step moved %2, less than a third of the standard uncertainty)</source>
        <translation>model: běh laboratoře s dt = %1 s (půlení kroku posunulo %2, méně než třetinu standardní nejistoty)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 does not move by itself (it is not a dynamic body): measure one that does</source>
        <translation>„%1“: %2 se samo nepohybuje (není to dynamické těleso): měřte takové, které se pohybuje</translation>
    </message>
    <message>
        <source>%1: time zero (%2 s) is so far from the file&apos;s times that they cannot be told apart</source>
        <translation>%1: nulový čas (%2 s) je tak daleko od časů v souboru, že je nelze rozlišit</translation>
    </message>
    <message>
        <source>the time column holds the time of every frame, not bounce times (name the column of bounce times &quot;bounce&quot;, or fit the positions with --quantity)</source>
        <translation>sloupec času obsahuje čas každého snímku, ne časy odrazů (pojmenujte sloupec časů odrazů „bounce“, nebo určujte z poloh s --quantity)</translation>
    </message>
    <message>
        <source>the fit was cancelled</source>
        <translation>určování z&#xa0;měření bylo zrušeno</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui</name>
    <message>
        <source>off</source>
        <translation>vypnuto</translation>
    </message>
    <message>
        <source>on</source>
        <translation>zapnuto</translation>
    </message>
    <message>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <source>%1 is %2, not %3</source>
        <translation>%1: %2, ne %3</translation>
    </message>
    <message>
        <source>%1 was changed during the run</source>
        <translation>%1: změněno během běhu</translation>
    </message>
    <message>
        <source>This question is asked with %1, which this step does not let you set (a mistake in the lesson): it is judged by that run done without the window.</source>
        <translation>Tato otázka se ptá na běh s nastavením %1, které vám tento krok nedovolí nastavit (chyba v lekci): odpověď se proto posoudí podle takového běhu spočítaného bez okna.</translation>
    </message>
    <message>
        <source>This question is asked with %1, from the start of the run. In your run %2: set it with the controls, press Reset and run again, then check.</source>
        <translation>Tato otázka se ptá na běh s nastavením %1 od jeho začátku; váš běh se liší (%2). Nastavte to v Ovládání, stiskněte Na začátek, spusťte běh znovu a pak odpověď zkontrolujte.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::BodyGraphDialog</name>
    <message>
        <source>A curve for each body</source>
        <translation>Křivka pro každé těleso</translation>
    </message>
    <message>
        <source>A curve of their sum</source>
        <translation>Křivka jejich součtu</translation>
    </message>
    <message>
        <source>In the centre-of-mass frame of these bodies</source>
        <translation>V těžišťové soustavě těchto těles</translation>
    </message>
    <message>
        <source>Graph of bodies</source>
        <translation>Graf těles</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>Veličina</translation>
    </message>
    <message>
        <source>Bodies</source>
        <translation>Tělesa</translation>
    </message>
    <message>
        <source>&amp;Quantity</source>
        <translation>&amp;Veličina</translation>
    </message>
    <message>
        <source>&amp;Bodies</source>
        <translation>&amp;Tělesa</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::BouncePanel</name>
    <message>
        <source>Heights of the centre above where it touched down. With a coefficient of restitution e, each bounce should reach e² times the one before.</source>
        <translation>Výšky středu nad místem, kde se míček dotkl podložky. Při koeficientu restituce e by měl každý odskok dosáhnout e²‑násobku předchozího.</translation>
    </message>
    <message>
        <source>Answer the lesson&apos;s question first</source>
        <translation>Nejdřív odpovězte na otázku lekce</translation>
    </message>
    <message>
        <source>ball</source>
        <translation>míček</translation>
    </message>
    <message>
        <source>e</source>
        <translation>e</translation>
    </message>
    <message>
        <source>drop h₀ [m]</source>
        <translation>pád h₀ [m]</translation>
    </message>
    <message>
        <source>h%1 [m]</source>
        <translation>h%1 [m]</translation>
    </message>
    <message>
        <source>h%1/h%2</source>
        <translation>h%1/h%2</translation>
    </message>
    <message>
        <source>no.</source>
        <comment>a bounce&apos;s number</comment>
        <translation>č.</translation>
    </message>
    <message>
        <source>The bounce: the drop, then the first bounce, the second…</source>
        <translation>Odskok: nejdřív pád, pak první odskok, druhý…</translation>
    </message>
    <message>
        <source>h
[m]</source>
        <translation>h
[m]</translation>
    </message>
    <message>
        <source>ratio</source>
        <translation>poměr</translation>
    </message>
    <message>
        <source>The height over the one before: compare it with e²</source>
        <translation>Výška dělená předchozí: porovnejte s&#xa0;e²</translation>
    </message>
    <message>
        <source>%1: e = %2, e² = %3</source>
        <translation>%1: e = %2, e² = %3</translation>
    </message>
    <message>
        <source>e = %1 (e² = %2)</source>
        <translation>e = %1 (e² = %2)</translation>
    </message>
    <message>
        <source>drop</source>
        <translation>pád</translation>
    </message>
    <message>
        <source>bounces</source>
        <translation>odrazy</translation>
    </message>
    <message>
        <source>Bounce heights</source>
        <translation>Výšky odskoků</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::ChoiceEditor</name>
    <message>
        <source>Options of the choice</source>
        <translation>Možnosti výběru</translation>
    </message>
    <message>
        <source>Add optio&amp;n</source>
        <translation>Přidat mo&amp;žnost</translation>
    </message>
    <message>
        <source>Remove option</source>
        <translation>Odebrat možnost</translation>
    </message>
    <message>
        <source>Option up</source>
        <translation>Možnost nahoru</translation>
    </message>
    <message>
        <source>Option down</source>
        <translation>Možnost dolů</translation>
    </message>
    <message>
        <source>The right option</source>
        <translation>Správná možnost</translation>
    </message>
    <message>
        <source>Ri&amp;ght option</source>
        <translation>Spr&amp;ávná možnost</translation>
    </message>
    <message>
        <source>Option %1</source>
        <translation>Možnost %1</translation>
    </message>
    <message>
        <source>&amp;Options (one language is enough)</source>
        <translation>&amp;Možnosti (stačí jeden jazyk)</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::ClassResultsDialog</name>
    <message>
        <source>Class results</source>
        <translation>Výsledky třídy</translation>
    </message>
    <message>
        <source>Folder of answers files</source>
        <translation>Složka se soubory s odpověďmi</translation>
    </message>
    <message>
        <source>the folder the class&apos;s answers files were saved in</source>
        <translation>složka, do které se uložily soubory s odpověďmi třídy</translation>
    </message>
    <message>
        <source>C&amp;hoose folder…</source>
        <translation>&amp;Zvolit složku…</translation>
    </message>
    <message>
        <source>Choose the folder of answers files</source>
        <translation>Zvolit složku se soubory s odpověďmi</translation>
    </message>
    <message>
        <source>&amp;Folder:</source>
        <translation>&amp;Složka:</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>Lekce</translation>
    </message>
    <message>
        <source>The lessons the folder holds answers to, the most answered first</source>
        <translation>Lekce, ke kterým jsou ve složce odpovědi, nejčastější první</translation>
    </message>
    <message>
        <source>&amp;Lesson:</source>
        <translation>&amp;Lekce:</translation>
    </message>
    <message>
        <source>What was collected</source>
        <translation>Co se sebralo</translation>
    </message>
    <message>
        <source>Class results table</source>
        <translation>Tabulka výsledků třídy</translation>
    </message>
    <message>
        <source>A row per student, per question the first answer, its verdict, the tries and hint or Show me used; the last row: the share right at the first answer</source>
        <translation>Řádek za každého žáka, u každé otázky první odpověď, její hodnocení, počet pokusů a použitá nápověda nebo Ukaž mi; poslední řádek: podíl správně napoprvé</translation>
    </message>
    <message>
        <source>Sort the table by</source>
        <translation>Řadit tabulku podle</translation>
    </message>
    <message>
        <source>&amp;Descending</source>
        <translation>S&amp;estupně</translation>
    </message>
    <message>
        <source>Sort descending</source>
        <translation>Řadit sestupně</translation>
    </message>
    <message>
        <source>&amp;Sort by:</source>
        <translation>Řadit &amp;podle:</translation>
    </message>
    <message>
        <source>Files left &amp;out:</source>
        <translation>&amp;Vynechané soubory:</translation>
    </message>
    <message>
        <source>Files left out, one line each</source>
        <translation>Vynechané soubory, po řádku</translation>
    </message>
    <message>
        <source>Export &amp;CSV…</source>
        <translation>Exportovat &amp;CSV…</translation>
    </message>
    <message>
        <source>Export the table as CSV</source>
        <translation>Exportovat tabulku jako CSV</translation>
    </message>
    <message>
        <source>Export &amp;PDF…</source>
        <translation>Exportovat P&amp;DF…</translation>
    </message>
    <message>
        <source>Export the table as PDF</source>
        <translation>Exportovat tabulku jako PDF</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zavřít</translation>
    </message>
    <message>
        <source>Choose the folder the class&apos;s answers files are in.</source>
        <translation>Zvolte složku, ve které jsou soubory s odpověďmi třídy.</translation>
    </message>
    <message>
        <source>%1: %2 students, %3 files left out</source>
        <translation>%1: žáků %2, vynechaných souborů %3</translation>
    </message>
    <message>
        <source>Export class results as CSV</source>
        <translation>Exportovat výsledky třídy jako CSV</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export se nezdařil</translation>
    </message>
    <message>
        <source>Export class results as PDF</source>
        <translation>Exportovat výsledky třídy jako PDF</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>Dokument PDF (*.pdf)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::CollisionPanel</name>
    <message>
        <source>x %1
y %2</source>
        <translation>x %1
y %2</translation>
    </message>
    <message>
        <source>Answer the lesson&apos;s question first</source>
        <translation>Nejdřív odpovězte na otázku lekce</translation>
    </message>
    <message>
        <source>quantity</source>
        <translation>veličina</translation>
    </message>
    <message>
        <source>before</source>
        <translation>před</translation>
    </message>
    <message>
        <source>after</source>
        <translation>po</translation>
    </message>
    <message>
        <source>No collision yet: run the simulation.</source>
        <translation>Zatím žádná srážka: spusťte simulaci.</translation>
    </message>
    <message>
        <source>collision</source>
        <translation>srazka</translation>
    </message>
    <message>
        <source>Collision of %1 and %2 at t = %3 s</source>
        <translation>Srážka: %1 a&#xa0;%2 v&#xa0;čase t&#xa0;=&#xa0;%3&#xa0;s</translation>
    </message>
    <message>
        <source>%1: velocity [m/s]</source>
        <translation>%1: rychlost [m/s]</translation>
    </message>
    <message>
        <source>%1: angular velocity ω [rad/s]</source>
        <translation>%1: úhlová rychlost ω [rad/s]</translation>
    </message>
    <message>
        <source>momentum p [kg m/s]</source>
        <translation>hybnost p [kg·m/s]</translation>
    </message>
    <message>
        <source>kinetic energy [J]</source>
        <translation>kinetická energie [J]</translation>
    </message>
    <message>
        <source>%1: ω by the full formula</source>
        <translation>%1: ω podle úplného vzorce</translation>
    </message>
    <message>
        <source>%1: ω without (r×n)²/I terms</source>
        <translation>%1: ω bez členů (r×n)²/I</translation>
    </message>
    <message>
        <source>(%1, %2)</source>
        <comment>a vector&apos;s x and y</comment>
        <translation>(%1; %2)</translation>
    </message>
    <message>
        <source>Velocities before and after</source>
        <translation>Rychlosti před a&#xa0;po</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::ColourField</name>
    <message>
        <source>Choose the body&apos;s colour</source>
        <translation>Zvolit barvu tělesa</translation>
    </message>
    <message>
        <source>default</source>
        <translation>výchozí</translation>
    </message>
    <message>
        <source>The body&apos;s colour as &quot;#rrggbb&quot; (six hexadecimal digits, as &quot;#d04030&quot;); empty for the default</source>
        <translation>Barva tělesa jako &quot;#rrggbb&quot; (šest šestnáctkových číslic, např. &quot;#d04030&quot;); prázdné pole dá výchozí barvu</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Výchozí</translation>
    </message>
    <message>
        <source>Take the body&apos;s own colour away: the view colours it</source>
        <translation>Odebrat tělesu vlastní barvu: obarví ho zobrazení</translation>
    </message>
    <message>
        <source>Body colour</source>
        <translation>Barva tělesa</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::ControlPanel</name>
    <message>
        <source>on</source>
        <translation>zapnuto</translation>
    </message>
    <message>
        <source>How positions and velocities are advanced in each step</source>
        <translation>Jak se v&#xa0;každém kroku posouvají polohy a&#xa0;rychlosti</translation>
    </message>
    <message>
        <source>Iterations</source>
        <translation>Iterace</translation>
    </message>
    <message>
        <source>Velocity iterations of the sequential-impulse solver</source>
        <translation>Rychlostní iterace řešiče s&#xa0;postupnými impulsy</translation>
    </message>
    <message>
        <source>dt</source>
        <translation>dt</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>The fixed time step [ms]</source>
        <translation>Pevný časový krok [ms]</translation>
    </message>
    <message>
        <source>Time scale</source>
        <translation>Časové měřítko</translation>
    </message>
    <message>
        <source>×</source>
        <translation>×</translation>
    </message>
    <message>
        <source>Slow motion below 1, fast forward above</source>
        <translation>Pod 1 zpomalení, nad 1 zrychlení</translation>
    </message>
    <message>
        <source>Restitution e</source>
        <translation>Koeficient restituce e</translation>
    </message>
    <message>
        <source>Coefficient of restitution e for every body: 0 sticks, 1 is elastic</source>
        <translation>Koeficient restituce e pro všechna tělesa: 0 – tělesa se slepí, 1 – pružný ráz</translation>
    </message>
    <message>
        <source>Friction μ</source>
        <translation>Tření μ</translation>
    </message>
    <message>
        <source>Coulomb friction coefficient μ for every body</source>
        <translation>Součinitel smykového (Coulombova) tření μ pro všechna tělesa</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrátor</translation>
    </message>
    <message>
        <source>Time step dt [ms]</source>
        <translation>Časový krok dt [ms]</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Řešič</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Tíhová síla</translation>
    </message>
    <message>
        <source>Fixed in this step of the lesson</source>
        <translation>V&#xa0;tomto kroku lekce pevně dané</translation>
    </message>
    <message>
        <source>The paper&apos;s impulse: one impulse per contact, once.
Sequential impulse: iterated, clamped, warm started.
Soft step: springy contacts solved in small substeps; stiff stacks.</source>
        <translation>Kontakt po kontaktu: jeden impuls na každý kontakt, jednou (metoda původního článku, ze kterého laboratoř vychází).
Postupné impulsy: iterované, omezené, s&#xa0;teplým startem.
Měkký krok: pružné kontakty řešené v&#xa0;malých podkrocích; pevné stohy.</translation>
    </message>
    <message>
        <source>Not used: the paper&apos;s impulse solves each contact once, in one pass</source>
        <translation>Nepoužívá se: řešič Kontakt po kontaktu řeší každý kontakt jednou, v&#xa0;jediném průchodu</translation>
    </message>
    <message numerus="yes">
        <source>Soft step: iterations of its bounce pass at the start of each step; the resting contacts are solved in %n substeps instead</source>
        <translation>
            <numerusform>Měkký krok: iterace průchodu odrazů na začátku každého kroku; kontakty v&#xa0;klidu se místo toho řeší v&#xa0;%n podkroku</numerusform>
            <numerusform>Měkký krok: iterace průchodu odrazů na začátku každého kroku; kontakty v&#xa0;klidu se místo toho řeší ve&#xa0;%n podkrocích</numerusform>
            <numerusform>Měkký krok: iterace průchodu odrazů na začátku každého kroku; kontakty v&#xa0;klidu se místo toho řeší v&#xa0;%n podkrocích</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::DivergenceBanner</name>
    <message>
        <source>Reset</source>
        <translation>Na začátek</translation>
    </message>
    <message>
        <source>Halve dt</source>
        <translation>Poloviční dt</translation>
    </message>
    <message>
        <source>Back to the start of the scene</source>
        <translation>Zpět na začátek scény</translation>
    </message>
    <message>
        <source>Back to the start with half the time step</source>
        <translation>Zpět na začátek s&#xa0;polovičním časovým krokem</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::EditTools</name>
    <message>
        <source>Select</source>
        <translation>Výběr</translation>
    </message>
    <message>
        <source>Select and move bodies; arrow keys nudge</source>
        <translation>Vybírat a&#xa0;posouvat tělesa; šipky posunou o&#xa0;kousek</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Otočení</translation>
    </message>
    <message>
        <source>Turn a body by dragging; Q and E turn by 5°</source>
        <translation>Otáčet tělesem tažením; Q a&#xa0;E otočí o&#xa0;5°</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>Kruh</translation>
    </message>
    <message>
        <source>Drag from the centre to draw a circle</source>
        <translation>Kruh nakreslíte tažením od středu</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Obdélník</translation>
    </message>
    <message>
        <source>Drag a rectangle to draw a box</source>
        <translation>Obdélník nakreslíte tažením</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Mnohoúhelník</translation>
    </message>
    <message>
        <source>Click the vertices; double-click or Enter closes the polygon</source>
        <translation>Klikejte na vrcholy; dvojklik nebo Enter mnohoúhelník uzavře</translation>
    </message>
    <message>
        <source>Ground</source>
        <translation>Podložka</translation>
    </message>
    <message>
        <source>Drag a rectangle to draw static ground or a wall</source>
        <translation>Statickou podložku nebo stěnu nakreslíte tažením obdélníku</translation>
    </message>
    <message>
        <source>Pin</source>
        <translation>Čep</translation>
    </message>
    <message>
        <source>Click a point of a body, then a second body or empty space for the world</source>
        <translation>Klikněte na bod tělesa, pak na druhé těleso nebo na prázdné místo pro okolí</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Pružina</translation>
    </message>
    <message>
        <source>Drag from one point to another; its rest length is the length drawn</source>
        <translation>Táhněte od jednoho bodu k&#xa0;druhému; klidová délka je nakreslená délka</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Smazat</translation>
    </message>
    <message>
        <source>Click a body to delete it with its springs and pins</source>
        <translation>Kliknutím smažete těleso i&#xa0;s&#xa0;jeho pružinami a&#xa0;čepy</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplikovat</translation>
    </message>
    <message>
        <source>Click a body to place a copy beside it</source>
        <translation>Kliknutím položíte vedle tělesa jeho kopii</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Editor</translation>
    </message>
    <message>
        <source>Delete selected body</source>
        <translation>Smazat vybrané těleso</translation>
    </message>
    <message>
        <source>Select a body to turn it</source>
        <translation>Vyberte těleso, které chcete otočit</translation>
    </message>
    <message>
        <source>Rotate %1</source>
        <translation>Otočit %1</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Posunout %1</translation>
    </message>
    <message>
        <source>Select a body to delete it</source>
        <translation>Vyberte těleso, které chcete smazat</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>Smazat %1</translation>
    </message>
    <message>
        <source>Not convex: it will be replaced by the convex hull shown</source>
        <translation>Nekonvexní: nahradí ho zobrazený konvexní obal</translation>
    </message>
    <message numerus="yes">
        <source>%n point(s); double-click or Enter closes the polygon, Escape drops it</source>
        <translation>
            <numerusform>%n bod; dvojklik nebo Enter mnohoúhelník uzavře, Escape ho zahodí</numerusform>
            <numerusform>%n body; dvojklik nebo Enter mnohoúhelník uzavře, Escape ho zahodí</numerusform>
            <numerusform>%n bodů; dvojklik nebo Enter mnohoúhelník uzavře, Escape ho zahodí</numerusform>
        </translation>
    </message>
    <message>
        <source>Click a point of a body to pin it</source>
        <translation>Klikněte na bod tělesa, které chcete připojit čepem</translation>
    </message>
    <message>
        <source>Now click a second body, or empty space to pin it to the world</source>
        <translation>Teď klikněte na druhé těleso, nebo na prázdné místo pro připojení k&#xa0;okolí</translation>
    </message>
    <message>
        <source>%1 at (%2; %3) m</source>
        <translation>%1 v&#xa0;(%2; %3)&#xa0;m</translation>
    </message>
    <message>
        <source>%1 at %2°</source>
        <translation>%1 pod úhlem %2°</translation>
    </message>
    <message>
        <source>Circle: centre (%1; %2) m, radius %3 m</source>
        <translation>Kruh: střed (%1; %2)&#xa0;m, poloměr %3&#xa0;m</translation>
    </message>
    <message>
        <source>%1 × %2 m</source>
        <translation>%1 × %2&#xa0;m</translation>
    </message>
    <message>
        <source>Spring: length %1 m</source>
        <translation>Pružina: délka %1&#xa0;m</translation>
    </message>
    <message>
        <source>Grid %1 m</source>
        <translation>Mřížka %1&#xa0;m</translation>
    </message>
    <message>
        <source>This lesson step locks the %1 tool</source>
        <translation>Tento krok lekce nástroj %1 zamyká</translation>
    </message>
    <message>
        <source>Set velocity of %1</source>
        <translation>Nastavit rychlost tělesa %1</translation>
    </message>
    <message>
        <source>%1: v = (%2; %3) m/s, |v| = %4 m/s (arrow: the distance covered in %5 s)</source>
        <translation>%1: v = (%2; %3) m/s, |v| = %4 m/s (šipka: dráha uražená za %5 s)</translation>
    </message>
    <message>
        <source>Delete spring from %1 to %2</source>
        <translation>Smazat pružinu %1 – %2</translation>
    </message>
    <message>
        <source>Add polygon %1</source>
        <translation>Přidat mnohoúhelník %1</translation>
    </message>
    <message>
        <source>Pin %1 to %2</source>
        <translation>Připnout %1 k&#xa0;%2</translation>
    </message>
    <message>
        <source>Duplicate %1 as %2</source>
        <translation>Duplikovat %1 jako %2</translation>
    </message>
    <message>
        <source>Add circle %1</source>
        <translation>Přidat kruh %1</translation>
    </message>
    <message>
        <source>Add box %1</source>
        <translation>Přidat obdélník %1</translation>
    </message>
    <message>
        <source>Add ground %1</source>
        <translation>Přidat podložku %1</translation>
    </message>
    <message>
        <source>Add spring from %1 to %2</source>
        <translation>Přidat pružinu %1 – %2</translation>
    </message>
    <message>
        <source>the world</source>
        <translation>svět</translation>
    </message>
    <message>
        <source>Pin %1 to the world</source>
        <translation>Připnout %1 ke světu</translation>
    </message>
    <message>
        <source>Snap to a grid of %1 m and to other bodies&apos; corners and edges (%2)</source>
        <translation>Přichytávat k&#xa0;mřížce %1&#xa0;m a&#xa0;k&#xa0;rohům a&#xa0;hranám jiných těles (%2)</translation>
    </message>
    <message>
        <source>This lesson step locks the %1 property</source>
        <translation>Tento krok lekce vlastnost %1 zamyká</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Rychlost</translation>
    </message>
    <message>
        <source>Edit the scene: draw bodies, pins and springs (%1); leaving it keeps the world paused at its start</source>
        <translation>Upravit scénu: kreslit tělesa, čepy a&#xa0;pružiny (%1); po opuštění editoru svět stojí na začátku</translation>
    </message>
    <message>
        <source>Edit mode: the world is paused at its start; press Space to run it</source>
        <translation>Editor: svět stojí na začátku; spustíte ho mezerníkem</translation>
    </message>
    <message>
        <source>The scene has no body to select</source>
        <translation>Ve scéně není žádné těleso, které by šlo vybrat</translation>
    </message>
    <message>
        <source>%1 selected</source>
        <translation>Vybráno: %1</translation>
    </message>
    <message>
        <source>Delete: click a body to delete it with its springs and pins; the Delete key deletes the selected body or spring</source>
        <translation>Smazat: kliknutím smažete těleso i&#xa0;s&#xa0;jeho pružinami a&#xa0;čepy; klávesa Delete smaže vybrané těleso nebo pružinu</translation>
    </message>
    <message>
        <source>Duplicate: click a body to place a copy beside it; Enter copies the selected body</source>
        <translation>Duplikovat: kliknutím položíte vedle tělesa jeho kopii; Enter zkopíruje vybrané těleso</translation>
    </message>
    <message>
        <source>Select a body to duplicate it</source>
        <translation>Vyberte těleso, které chcete duplikovat</translation>
    </message>
    <message>
        <source>Pin: click a point of a body, then a second body or empty space for the world; Enter pins the selected body to the world at its centre</source>
        <translation>Čep: klikněte na bod tělesa, pak na druhé těleso nebo na prázdné místo pro okolí; Enter připne vybrané těleso k&#xa0;okolí v&#xa0;jeho středu</translation>
    </message>
    <message>
        <source>Polygon: click the vertices, then double-click or press Enter to close it; Backspace drops the last point; Enter with no points adds a triangle</source>
        <translation>Mnohoúhelník: klikejte na vrcholy, dvojklikem nebo klávesou Enter ho uzavřete; Backspace odebere poslední bod; Enter bez bodů přidá trojúhelník</translation>
    </message>
    <message>
        <source>Rotate: drag a body, or anywhere for the selected one, to turn it about its origin; a click selects, and so does Enter, body after body; Q and E turn the selected body by 5°</source>
        <translation>Otočení: tažením tělesa (nebo kdekoli pro vybrané těleso) ho otočíte kolem jeho počátku; kliknutí vybírá, Enter vybírá jedno těleso po druhém; Q a&#xa0;E otočí vybrané těleso o&#xa0;5°</translation>
    </message>
    <message>
        <source>Select: click a body or a spring to select it, drag a body to move it, drag the arrow&apos;s handle to set its velocity; Enter selects the next body, the arrow keys nudge, Q and E turn</source>
        <translation>Výběr: kliknutím vyberete těleso nebo pružinu, tažením těleso posunete, tažením konce šipky nastavíte jeho rychlost; Enter vybere další těleso, šipky posunou o&#xa0;kousek, Q a&#xa0;E otočí</translation>
    </message>
    <message>
        <source>Circle: drag from the centre outwards to draw one; a click draws nothing; Enter adds one at the view&apos;s centre</source>
        <translation>Kruh: nakreslíte ho tažením od středu ven; samotné kliknutí nic nenakreslí; Enter přidá kruh doprostřed pohledu</translation>
    </message>
    <message>
        <source>Box: drag from corner to corner to draw one; a click draws nothing; Enter adds one at the view&apos;s centre</source>
        <translation>Obdélník: nakreslíte ho tažením z&#xa0;rohu do rohu; samotné kliknutí nic nenakreslí; Enter přidá obdélník doprostřed pohledu</translation>
    </message>
    <message>
        <source>Ground: drag from corner to corner to draw static ground or a wall; a click draws nothing; Enter adds a floor at the view&apos;s centre</source>
        <translation>Podložka: statickou podložku nebo stěnu nakreslíte tažením z&#xa0;rohu do rohu; samotné kliknutí nic nenakreslí; Enter přidá podlahu doprostřed pohledu</translation>
    </message>
    <message>
        <source>Spring: drag from one point to another (a body or empty space, the world, at each end); a click draws nothing; Enter hangs the selected body from the world</source>
        <translation>Pružina: táhněte od jednoho bodu k&#xa0;druhému (na každém konci těleso, nebo prázdné místo pro okolí); samotné kliknutí nic nenakreslí; Enter zavěsí vybrané těleso na okolí</translation>
    </message>
    <message>
        <source>Select a body to hang it from a spring</source>
        <translation>Vyberte těleso, které chcete zavěsit na pružinu</translation>
    </message>
    <message>
        <source>Add a body at the view&apos;s centre</source>
        <translation>Přidat těleso doprostřed pohledu</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::ErrorPanel</name>
    <message>
        <source>Run</source>
        <translation>Spustit</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>The reference problem whose diagram is shown</source>
        <translation>Referenční úloha, jejíž diagram je zobrazen</translation>
    </message>
    <message>
        <source>Problem</source>
        <translation>Úloha</translation>
    </message>
    <message>
        <source>Running every integrator on every reference problem…</source>
        <translation>Každý integrátor běží na každé referenční úloze…</translation>
    </message>
    <message>
        <source>Cancelling after the row in progress…</source>
        <translation>Zruší se po dokončení rozpracovaného řádku…</translation>
    </message>
    <message>
        <source>Cancelled after %1 rows.</source>
        <translation>Zrušeno, hotové řádky: %1.</translation>
    </message>
    <message>
        <source>%1 rows: CPU time of each run is the smallest of repeated runs.</source>
        <translation>Počet řádků: %1. Čas CPU každého běhu je nejkratší z&#xa0;opakovaných běhů.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::FittingTable</name>
    <message>
        <source>Export as CSV…</source>
        <translation>Exportovat do CSV…</translation>
    </message>
    <message>
        <source>Save CSV…</source>
        <translation>Uložit CSV…</translation>
    </message>
    <message>
        <source>Save the table as a CSV file (decimal point, full precision) for a spreadsheet</source>
        <translation>Uložit tabulku jako soubor CSV (desetinná tečka, plná přesnost) pro tabulkový procesor</translation>
    </message>
    <message>
        <source>Export table as CSV</source>
        <translation>Exportovat tabulku do CSV</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export se nezdařil</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopírovat</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>prázdné</translation>
    </message>
    <message>
        <source>Measuring the run so far…</source>
        <translation>Měřím dosavadní běh…</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::ForcesView</name>
    <message>
        <source>(%1, %2)</source>
        <translation>(%1; %2)</translation>
    </message>
    <message>
        <source>weight m g</source>
        <translation>tíha m g</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>odpor prostředí</translation>
    </message>
    <message>
        <source>spring %1</source>
        <translation>pružina %1</translation>
    </message>
    <message>
        <source>your pull</source>
        <translation>váš tah</translation>
    </message>
    <message>
        <source>gravitation</source>
        <translation>gravitace</translation>
    </message>
    <message>
        <source>force</source>
        <translation>síla</translation>
    </message>
    <message>
        <source>F [N]</source>
        <translation>F [N]</translation>
    </message>
    <message>
        <source>acts at r [m]</source>
        <translation>působí v r [m]</translation>
    </message>
    <message>
        <source>τ = r × F [N·m]</source>
        <translation>τ = r × F [N·m]</translation>
    </message>
    <message>
        <source>the accumulators</source>
        <translation>střadače</translation>
    </message>
    <message>
        <source>a = F / m = %1 m/s², α = τ / I = %2 rad/s²</source>
        <translation>a = F / m = %1 m/s², α = τ / I = %2 rad/s²</translation>
    </message>
    <message>
        <source>Forces on this body</source>
        <translation>Síly na toto těleso</translation>
    </message>
    <message>
        <source>Show the forces on this body</source>
        <translation>Zobrazit síly na toto těleso</translation>
    </message>
    <message>
        <source>Free-body diagram</source>
        <translation>Silový diagram tělesa</translation>
    </message>
    <message>
        <source>Forces and their sums</source>
        <translation>Síly a jejich součty</translation>
    </message>
    <message>
        <source>No force acts on this body.</source>
        <translation>Na toto těleso nepůsobí žádná síla.</translation>
    </message>
    <message>
        <source>Click a body to see the forces on it.</source>
        <translation>Klepněte na těleso a uvidíte síly, které na ně působí.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::ImpulseFormulaView</name>
    <message>
        <source>Impulse formula</source>
        <translation>Vzorec pro impuls</translation>
    </message>
    <message>
        <source>The numbers of the first collision appear here when it happens.</source>
        <translation>Čísla první srážky se tu objeví, jakmile k&#xa0;ní dojde.</translation>
    </message>
    <message>
        <source>The impulse formula with this collision&apos;s numbers</source>
        <translation>Vzorec impulsu s&#xa0;čísly této srážky</translation>
    </message>
    <message>
        <source>Show the impulse formula</source>
        <translation>Zobrazit vzorec pro impuls</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::InspectorPanel</name>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>Mass m</source>
        <translation>Hmotnost m</translation>
    </message>
    <message>
        <source>The body&apos;s mass; its moment of inertia scales with it</source>
        <translation>Hmotnost tělesa; moment setrvačnosti se mění úměrně s&#xa0;ní</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Těleso</translation>
    </message>
    <message>
        <source>Inertia I</source>
        <translation>Moment setrvačnosti I</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Poloha</translation>
    </message>
    <message>
        <source>Angle θ</source>
        <translation>Úhel θ</translation>
    </message>
    <message>
        <source>Velocity v</source>
        <translation>Rychlost v</translation>
    </message>
    <message>
        <source>Angular vel. ω</source>
        <translation>Úhlová rychlost ω</translation>
    </message>
    <message>
        <source>Kinetic energy</source>
        <translation>Kinetická energie</translation>
    </message>
    <message>
        <source>%1 kg</source>
        <translation>%1&#xa0;kg</translation>
    </message>
    <message>
        <source>%1 kg·m²</source>
        <translation>%1&#xa0;kg·m²</translation>
    </message>
    <message>
        <source>infinite</source>
        <translation>nekonečno</translation>
    </message>
    <message>
        <source>(%1, %2) m</source>
        <translation>(%1; %2)&#xa0;m</translation>
    </message>
    <message>
        <source>%1 rad</source>
        <translation>%1&#xa0;rad</translation>
    </message>
    <message>
        <source>(%1, %2) m/s</source>
        <translation>(%1; %2)&#xa0;m/s</translation>
    </message>
    <message>
        <source>%1 rad/s</source>
        <translation>%1&#xa0;rad/s</translation>
    </message>
    <message>
        <source>Speed |v|</source>
        <translation>Velikost rychlosti |v|</translation>
    </message>
    <message>
        <source>%1 m/s</source>
        <translation>%1&#xa0;m/s</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>%1&#xa0;°/s</source>
        <translation>%1&#xa0;°/s</translation>
    </message>
    <message>
        <source>°</source>
        <comment>angle unit: degrees</comment>
        <translation>°</translation>
    </message>
    <message>
        <source>rad</source>
        <comment>angle unit: radians</comment>
        <translation>rad</translation>
    </message>
    <message>
        <source>degrees</source>
        <translation>stupně</translation>
    </message>
    <message>
        <source>radians</source>
        <translation>radiány</translation>
    </message>
    <message>
        <source>Unit of angles</source>
        <translation>Jednotka úhlů</translation>
    </message>
    <message>
        <source>Angles and angular velocities in degrees or in radians</source>
        <translation>Úhly a úhlové rychlosti ve stupních nebo v radiánech</translation>
    </message>
    <message>
        <source>Graph…</source>
        <translation>Graf…</translation>
    </message>
    <message>
        <source>A graph of this body&apos;s quantities against time</source>
        <translation>Graf veličin tohoto tělesa v závislosti na čase</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <comment>a value named by its row</comment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>No body selected</source>
        <translation>Není vybráno žádné těleso</translation>
    </message>
    <message>
        <source>Click a body in the scene, or select one there with ]</source>
        <translation>Klikněte na těleso ve scéně nebo ho tam vyberte klávesou ]</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::Instruments</name>
    <message>
        <source>Graph: %1</source>
        <translation>Graf: %1</translation>
    </message>
    <message>
        <source>Graph: %1 (centre-of-mass frame)</source>
        <translation>Graf: %1 (těžišťová soustava)</translation>
    </message>
    <message>
        <source>&amp;Graph of bodies…</source>
        <translation>&amp;Graf těles…</translation>
    </message>
    <message>
        <source>Plot a quantity of chosen bodies against time</source>
        <translation>Graf veličiny vybraných těles v závislosti na čase</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::InstrumentsPanel</name>
    <message>
        <source>ruler: %1</source>
        <translation>pravítko: %1</translation>
    </message>
    <message>
        <source>angle: %1</source>
        <translation>úhel: %1</translation>
    </message>
    <message>
        <source>stopwatch line, %1</source>
        <translation>čára stopek, %1</translation>
    </message>
    <message>
        <source>Ruler</source>
        <translation>Pravítko</translation>
    </message>
    <message>
        <source>Protractor</source>
        <translation>Úhloměr</translation>
    </message>
    <message>
        <source>Stopwatch</source>
        <translation>Stopky</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Sonda</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Soustava</translation>
    </message>
    <message>
        <source>Instruments</source>
        <translation>Měřidla</translation>
    </message>
    <message>
        <source>Ruler start x</source>
        <translation>Začátek pravítka x</translation>
    </message>
    <message>
        <source>Ruler start y</source>
        <translation>Začátek pravítka y</translation>
    </message>
    <message>
        <source>Ruler end x</source>
        <translation>Konec pravítka x</translation>
    </message>
    <message>
        <source>Ruler end y</source>
        <translation>Konec pravítka y</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Začátek</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Konec</translation>
    </message>
    <message>
        <source>Snap to centres and corners</source>
        <translation>Přichytávat ke středům a rohům</translation>
    </message>
    <message>
        <source>An end near a body&apos;s centre of mass or corner goes exactly there</source>
        <translation>Konec blízko těžiště nebo rohu tělesa se umístí přesně tam</translation>
    </message>
    <message>
        <source>Length measured by the ruler</source>
        <translation>Délka změřená pravítkem</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Délka</translation>
    </message>
    <message>
        <source>Drag on the scene with Shift held to lay the ruler; drag its ends to move them.</source>
        <translation>Pravítko položíte tažením ve scéně s přidrženou klávesou Shift; jeho konce přesunete tažením.</translation>
    </message>
    <message>
        <source>Angle of a body</source>
        <translation>Úhel tělesa</translation>
    </message>
    <message>
        <source>Angle between two lines</source>
        <translation>Úhel mezi dvěma přímkami</translation>
    </message>
    <message>
        <source>What the protractor measures</source>
        <translation>Co úhloměr měří</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Měřit</translation>
    </message>
    <message>
        <source>Body the protractor measures</source>
        <translation>Těleso, které úhloměr měří</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Těleso</translation>
    </message>
    <message>
        <source>Vertex x</source>
        <translation>Vrchol x</translation>
    </message>
    <message>
        <source>Vertex y</source>
        <translation>Vrchol y</translation>
    </message>
    <message>
        <source>First line through x</source>
        <translation>První přímka prochází x</translation>
    </message>
    <message>
        <source>First line through y</source>
        <translation>První přímka prochází y</translation>
    </message>
    <message>
        <source>Second line through x</source>
        <translation>Druhá přímka prochází x</translation>
    </message>
    <message>
        <source>Second line through y</source>
        <translation>Druhá přímka prochází y</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Vrchol</translation>
    </message>
    <message>
        <source>First line</source>
        <translation>První přímka</translation>
    </message>
    <message>
        <source>Second line</source>
        <translation>Druhá přímka</translation>
    </message>
    <message>
        <source>Angle measured by the protractor</source>
        <translation>Úhel změřený úhloměrem</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Úhel</translation>
    </message>
    <message>
        <source>Start button</source>
        <translation>tlačítko Start</translation>
    </message>
    <message>
        <source>Stop button</source>
        <translation>tlačítko Stop</translation>
    </message>
    <message>
        <source>first contact of the body</source>
        <translation>první dotyk tělesa</translation>
    </message>
    <message>
        <source>the body passing the line</source>
        <translation>průchod tělesa čarou</translation>
    </message>
    <message>
        <source>the body coming to rest</source>
        <translation>zastavení tělesa</translation>
    </message>
    <message>
        <source>Time on the stopwatch</source>
        <translation>Čas na stopkách</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Čas</translation>
    </message>
    <message>
        <source>Stopwatch state</source>
        <translation>Stav stopek</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Stav</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Vynulovat</translation>
    </message>
    <message>
        <source>What starts the stopwatch</source>
        <translation>Co stopky spustí</translation>
    </message>
    <message>
        <source>What stops the stopwatch</source>
        <translation>Co stopky zastaví</translation>
    </message>
    <message>
        <source>Starts on</source>
        <translation>Spustí</translation>
    </message>
    <message>
        <source>Stops on</source>
        <translation>Zastaví</translation>
    </message>
    <message>
        <source>Body the stopwatch watches</source>
        <translation>Těleso, které stopky sledují</translation>
    </message>
    <message>
        <source>Height of the line</source>
        <translation>Výška čáry</translation>
    </message>
    <message>
        <source>The horizontal line y = h that the body&apos;s centre passes</source>
        <translation>Vodorovná čára y = h, kterou prochází těžiště tělesa</translation>
    </message>
    <message>
        <source>Line at height y</source>
        <translation>Čára ve výšce y</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>připraveny</translation>
    </message>
    <message>
        <source>waiting for the start event</source>
        <translation>čekají na událost, která je spustí</translation>
    </message>
    <message>
        <source>running</source>
        <translation>běží</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>zastaveny</translation>
    </message>
    <message>
        <source>Body the probe reads</source>
        <translation>Těleso, které sonda měří</translation>
    </message>
    <message>
        <source>Probe reading</source>
        <translation>Údaje sondy</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopírovat</translation>
    </message>
    <message>
        <source>Puts the probe&apos;s numbers on the clipboard</source>
        <translation>Zkopíruje údaje sondy do schránky</translation>
    </message>
    <message>
        <source>Plot…</source>
        <translation>Graf…</translation>
    </message>
    <message>
        <source>A graph of this body&apos;s quantities against time</source>
        <translation>Graf veličin tohoto tělesa v závislosti na čase</translation>
    </message>
    <message>
        <source>no body chosen</source>
        <translation>není vybráno žádné těleso</translation>
    </message>
    <message>
        <source>x = %1</source>
        <translation>x = %1</translation>
    </message>
    <message>
        <source>y = %1</source>
        <translation>y = %1</translation>
    </message>
    <message>
        <source>v = %1</source>
        <translation>v = %1</translation>
    </message>
    <message>
        <source>|v| = %1</source>
        <translation>|v| = %1</translation>
    </message>
    <message>
        <source>ω = %1</source>
        <translation>ω = %1</translation>
    </message>
    <message>
        <source>E_k = %1</source>
        <translation>E_k = %1</translation>
    </message>
    <message>
        <source>p = %1</source>
        <translation>p = %1</translation>
    </message>
    <message>
        <source>L = %1</source>
        <translation>L = %1</translation>
    </message>
    <message>
        <source>weight = %1</source>
        <translation>tíha = %1</translation>
    </message>
    <message>
        <source>contact force = %1</source>
        <translation>kontaktní síla = %1</translation>
    </message>
    <message>
        <source>%1 at t = %2&#xa0;s</source>
        <translation>%1 v čase t = %2&#xa0;s</translation>
    </message>
    <message>
        <source>Lab frame</source>
        <translation>Laboratorní soustava</translation>
    </message>
    <message>
        <source>Centre-of-mass frame of the bodies ticked</source>
        <translation>Těžišťová soustava zaškrtnutých těles</translation>
    </message>
    <message>
        <source>Frame of reference</source>
        <translation>Vztažná soustava</translation>
    </message>
    <message>
        <source>Bodies of the centre-of-mass frame</source>
        <translation>Tělesa těžišťové soustavy</translation>
    </message>
    <message>
        <source>Plot momenta in this frame…</source>
        <translation>Graf hybností v této soustavě…</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::JobProgress</name>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::LessonDraft</name>
    <message>
        <source>Step 1</source>
        <translation>Krok 1</translation>
    </message>
    <message>
        <source>Edit text</source>
        <translation>Úprava textu</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Krok %1</translation>
    </message>
    <message>
        <source>Add step</source>
        <translation>Přidání kroku</translation>
    </message>
    <message>
        <source>Remove step</source>
        <translation>Odebrání kroku</translation>
    </message>
    <message>
        <source>Move step</source>
        <translation>Přesun kroku</translation>
    </message>
    <message>
        <source>Duplicate step</source>
        <translation>Zdvojení kroku</translation>
    </message>
    <message>
        <source>Set scene</source>
        <translation>Nastavení scény</translation>
    </message>
    <message>
        <source>Set author</source>
        <translation>Nastavení autora</translation>
    </message>
    <message>
        <source>new lesson.rlesson</source>
        <translation>nová lekce.rlesson</translation>
    </message>
    <message>
        <source>The lesson has no file yet: use Save As.</source>
        <translation>Lekce ještě nemá soubor: použijte Uložit jako.</translation>
    </message>
    <message>
        <source>%1: a lesson is saved as one file ending in .rlesson</source>
        <translation>%1: lekce se ukládá jako jeden soubor s příponou .rlesson</translation>
    </message>
    <message>
        <source>%1 comes with RigidLab and is not overwritten.</source>
        <translation>%1 je součástí RigidLabu a nepřepíše se.</translation>
    </message>
    <message>
        <source>Step %1 has no scene yet.</source>
        <translation>Krok %1 zatím nemá scénu.</translation>
    </message>
    <message>
        <source>step %1&apos;s scene</source>
        <translation>scéna kroku %1</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::LessonEditor</name>
    <message>
        <source>Lesson editor</source>
        <translation>Editor lekcí</translation>
    </message>
    <message>
        <source>Problems of the lesson</source>
        <translation>Problémy lekce</translation>
    </message>
    <message>
        <source>Lesson &amp;title</source>
        <translation>&amp;Název lekce</translation>
    </message>
    <message>
        <source>&amp;Summary</source>
        <translation>S&amp;hrnutí</translation>
    </message>
    <message>
        <source>&amp;Level</source>
        <translation>Ú&amp;roveň</translation>
    </message>
    <message>
        <source>M&amp;inutes</source>
        <translation>M&amp;inuty</translation>
    </message>
    <message>
        <source>not said</source>
        <translation>neuvedeno</translation>
    </message>
    <message>
        <source>&#xa0;min</source>
        <translation>&#xa0;min</translation>
    </message>
    <message>
        <source>Minutes the lesson takes</source>
        <translation>Kolik minut lekce trvá</translation>
    </message>
    <message>
        <source>minutes</source>
        <translation>minuty</translation>
    </message>
    <message>
        <source>St&amp;eps</source>
        <translation>&amp;Kroky</translation>
    </message>
    <message>
        <source>Steps of the lesson</source>
        <translation>Kroky lekce</translation>
    </message>
    <message>
        <source>Add step</source>
        <translation>Přidat krok</translation>
    </message>
    <message>
        <source>Remove step</source>
        <translation>Odebrat krok</translation>
    </message>
    <message>
        <source>Move up</source>
        <translation>Posunout nahoru</translation>
    </message>
    <message>
        <source>Move down</source>
        <translation>Posunout dolů</translation>
    </message>
    <message>
        <source>Duplicate step</source>
        <translation>Zdvojit krok</translation>
    </message>
    <message>
        <source>Try as a student</source>
        <translation>Vyzkoušet jako žák</translation>
    </message>
    <message>
        <source>Step title (%1)</source>
        <translation>Název kroku (%1)</translation>
    </message>
    <message>
        <source>Step text (%1)</source>
        <translation>Text kroku (%1)</translation>
    </message>
    <message>
        <source>Preview (%1)</source>
        <translation>Náhled (%1)</translation>
    </message>
    <message>
        <source>As the student sees it (%1)</source>
        <translation>Jak to uvidí žák (%1)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Zpět</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>Z&amp;novu</translation>
    </message>
    <message>
        <source>&amp;Save lesson</source>
        <translation>&amp;Uložit lekci</translation>
    </message>
    <message>
        <source>Save lesson &amp;as…</source>
        <translation>Uložit lekci &amp;jako…</translation>
    </message>
    <message>
        <source>New lesson</source>
        <translation>Nová lekce</translation>
    </message>
    <message>
        <source>Save lesson</source>
        <translation>Uložit lekci</translation>
    </message>
    <message>
        <source>lesson</source>
        <translation>lekce</translation>
    </message>
    <message>
        <source>Save lesson as</source>
        <translation>Uložit lekci jako</translation>
    </message>
    <message>
        <source>Lessons in one file (*.rlesson)</source>
        <translation>Lekce v&#xa0;jednom souboru (*.rlesson)</translation>
    </message>
    <message>
        <source>no %1</source>
        <translation>chybí %1</translation>
    </message>
    <message numerus="yes">
        <source>%n problem(s)</source>
        <translation>
            <numerusform>%n problém</numerusform>
            <numerusform>%n problémy</numerusform>
            <numerusform>%n problémů</numerusform>
        </translation>
    </message>
    <message>
        <source>%1. %2 — ⚠ %3</source>
        <translation>%1. %2 — ⚠ %3</translation>
    </message>
    <message>
        <source>No problems found.</source>
        <translation>Žádné problémy.</translation>
    </message>
    <message>
        <source>new lesson</source>
        <translation>nová lekce</translation>
    </message>
    <message>
        <source>%1%2 — Lesson editor — RigidLab</source>
        <translation>%1%2 – Editor lekcí – RigidLab</translation>
    </message>
    <message>
        <source>The lesson has unsaved changes. Save them?</source>
        <translation>Lekce má neuložené změny. Uložit je?</translation>
    </message>
    <message>
        <source>The step&apos;s questions and settings</source>
        <translation>Otázky a nastavení kroku</translation>
    </message>
    <message>
        <source>Questions</source>
        <translation>Otázky</translation>
    </message>
    <message>
        <source>Shown and locked</source>
        <translation>Zobrazeno a zamčeno</translation>
    </message>
    <message>
        <source>Edit t&amp;he step&apos;s scene in the window</source>
        <translation>Upr&amp;avit scénu kroku v okně</translation>
    </message>
    <message>
        <source>Opens this step&apos;s scene in the main window&apos;s scene editor</source>
        <translation>Otevře scénu tohoto kroku v editoru scén hlavního okna</translation>
    </message>
    <message>
        <source>Take the &amp;window&apos;s scene for this step</source>
        <translation>Převzít s&amp;cénu z okna pro tento krok</translation>
    </message>
    <message>
        <source>The scene open in the main window, as edited there, becomes this step&apos;s scene</source>
        <translation>Scéna otevřená v hlavním okně, tak jak je tam upravená, se stane scénou tohoto kroku</translation>
    </message>
    <message>
        <source>Step %1: %2</source>
        <translation>Krok %1: %2</translation>
    </message>
    <message>
        <source>Running the steps&apos; scenes to check them…</source>
        <translation>Scény kroků se spouštějí ke kontrole…</translation>
    </message>
    <message>
        <source>What the student reads in this step: **bold**, *italic*, a line that starts with “- ” is a list item</source>
        <translation>Co žák v tomto kroku čte: **tučně**, *kurzívou*, řádek začínající „- “ je položka seznamu</translation>
    </message>
    <message>
        <source>The step&apos;s scene does not open: %1</source>
        <translation>Scénu kroku nelze otevřít: %1</translation>
    </message>
    <message>
        <source>⚠ %1: not written yet; the student reads the %2 text</source>
        <translation>⚠ %1: zatím nenapsáno; žák čte text v jazyce %2</translation>
    </message>
    <message>
        <source>Checking the steps&apos; scenes</source>
        <translation>Kontrola scén kroků</translation>
    </message>
    <message>
        <source>Cancel checking the steps&apos; scenes</source>
        <translation>Zrušit kontrolu scén kroků</translation>
    </message>
    <message>
        <source>The steps&apos; scenes were not checked: the checks were cancelled.</source>
        <translation>Scény kroků nebyly zkontrolovány: kontrola byla zrušena.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::LessonPlayer</name>
    <message>
        <source>◀ Back</source>
        <translation>◀ Zpět</translation>
    </message>
    <message>
        <source>Restart step</source>
        <translation>Krok znovu</translation>
    </message>
    <message>
        <source>Next ▶</source>
        <translation>Další ▶</translation>
    </message>
    <message>
        <source>Export plots…</source>
        <translation>Exportovat grafy…</translation>
    </message>
    <message>
        <source>Start the first lesson</source>
        <translation>Začít první lekci</translation>
    </message>
    <message>
        <source>The lessons that come with RigidLab (File › Open lesson for others)</source>
        <translation>Lekce dodávané s&#xa0;RigidLabem (další otevřete přes Soubor › Otevřít lekci)</translation>
    </message>
    <message>
        <source>Introduction</source>
        <translation>Úvod</translation>
    </message>
    <message>
        <source>Show or hide the lesson&apos;s introduction</source>
        <translation>Zobrazit nebo skrýt úvod lekce</translation>
    </message>
    <message>
        <source>Cannot open lesson</source>
        <translation>Lekci nelze otevřít</translation>
    </message>
    <message>
        <source>Choose a lesson…</source>
        <translation>Vyberte lekci…</translation>
    </message>
    <message>
        <source>%1: the lesson has no steps</source>
        <translation>%1: lekce nemá žádné kroky</translation>
    </message>
    <message>
        <source>Start here</source>
        <translation>Začněte zde</translation>
    </message>
    <message>
        <source>RigidLab is a laboratory of moving bodies: run a prepared scene, change its settings and measure what happens. Each lesson walks you through one idea of mechanics step by step, with questions to answer on the way.</source>
        <translation>RigidLab je laboratoř pohybujících se těles: spusťte připravenou scénu, změňte její nastavení a&#xa0;změřte, co se stane. Každá lekce vás krok za krokem provede jednou myšlenkou mechaniky a&#xa0;cestou vám položí otázky.</translation>
    </message>
    <message>
        <source>The first lesson is “%1”; the list above holds the others.</source>
        <translation>První lekce je „%1“; ostatní najdete v&#xa0;seznamu nahoře.</translation>
    </message>
    <message>
        <source>%1 · about %2 min</source>
        <translation>%1 · asi %2&#xa0;min</translation>
    </message>
    <message>
        <source>Step %1 of %2</source>
        <translation>Krok %1 z&#xa0;%2</translation>
    </message>
    <message>
        <source>your answer</source>
        <translation>vaše odpověď</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Zkontrolovat</translation>
    </message>
    <message>
        <source>Show me</source>
        <translation>Ukaž mi</translation>
    </message>
    <message>
        <source>Give up and show the measured value</source>
        <translation>Vzdát to a&#xa0;ukázat naměřenou hodnotu</translation>
    </message>
    <message>
        <source>Type a number first.</source>
        <translation>Nejdřív zadejte číslo.</translation>
    </message>
    <message>
        <source>Type a number from %1 to %2.</source>
        <translation>Zadejte číslo od %1 do %2.</translation>
    </message>
    <message>
        <source>The lesson was not opened: the edited scene stays.</source>
        <translation>Lekce nebyla otevřena: upravovaná scéna zůstává.</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Jméno:</translation>
    </message>
    <message>
        <source>C&amp;lass:</source>
        <translation>&amp;Třída:</translation>
    </message>
    <message>
        <source>Your name</source>
        <translation>Vaše jméno</translation>
    </message>
    <message>
        <source>Your name, for the worksheet you hand in</source>
        <translation>Vaše jméno na pracovní list, který odevzdáte</translation>
    </message>
    <message>
        <source>Your class</source>
        <translation>Vaše třída</translation>
    </message>
    <message>
        <source>Your class, for the worksheet you hand in</source>
        <translation>Vaše třída na pracovní list, který odevzdáte</translation>
    </message>
    <message>
        <source>Open a lesson first.</source>
        <translation>Nejdřív otevřete lekci.</translation>
    </message>
    <message>
        <source>Hand in</source>
        <translation>Odevzdat</translation>
    </message>
    <message>
        <source>Type your name first: it goes on the worksheet.</source>
        <translation>Nejdřív napište své jméno: patří na pracovní list.</translation>
    </message>
    <message>
        <source>Hand in the worksheet</source>
        <translation>Odevzdat pracovní list</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>Dokument PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Cannot hand in</source>
        <translation>Nelze odevzdat</translation>
    </message>
    <message>
        <source>Handed in</source>
        <translation>Odevzdáno</translation>
    </message>
    <message>
        <source>Your worksheet is in %1, your answers beside it in %2.</source>
        <translation>Váš pracovní list je v&#xa0;%1, vaše odpovědi vedle něj v&#xa0;%2.</translation>
    </message>
    <message>
        <source>Finish: hand in the worksheet…</source>
        <translation>Konec: odevzdat pracovní list…</translation>
    </message>
    <message>
        <source>Hand in…</source>
        <translation>Odevzdat…</translation>
    </message>
    <message>
        <source>Write your worksheet as a PDF: the questions, your answers and their verdicts, the plots and the settings (%1)</source>
        <translation>Zapíše váš pracovní list jako PDF: otázky, vaše odpovědi a&#xa0;jejich hodnocení, grafy a&#xa0;nastavení (%1)</translation>
    </message>
    <message>
        <source>Works&amp;heet to print…</source>
        <translation>&amp;Pracovní list k&#xa0;tisku…</translation>
    </message>
    <message>
        <source>The open lesson&apos;s questions with lines to write on, and its figures</source>
        <translation>Otázky otevřené lekce s&#xa0;řádky na psaní a&#xa0;její obrázky</translation>
    </message>
    <message>
        <source>Teacher&apos;s &amp;key…</source>
        <translation>&amp;Klíč pro učitele…</translation>
    </message>
    <message>
        <source>The open lesson&apos;s questions with the values the simulation measures</source>
        <translation>Otázky otevřené lekce s&#xa0;hodnotami, které simulace naměří</translation>
    </message>
    <message>
        <source>Teacher&apos;s key</source>
        <translation>Klíč pro učitele</translation>
    </message>
    <message>
        <source>Worksheet to print</source>
        <translation>Pracovní list k&#xa0;tisku</translation>
    </message>
    <message>
        <source>Cannot write the worksheet</source>
        <translation>Pracovní list nelze zapsat</translation>
    </message>
    <message>
        <source>Step text</source>
        <translation>Text kroku</translation>
    </message>
    <message>
        <source>your answer, in %1</source>
        <translation>vaše odpověď, v&#xa0;jednotkách %1</translation>
    </message>
    <message>
        <source>Check the option chosen</source>
        <translation>Zkontrolovat zvolenou možnost</translation>
    </message>
    <message>
        <source>Give up and show the right answer</source>
        <translation>Vzdát to a ukázat správnou odpověď</translation>
    </message>
    <message>
        <source>Choose an answer first.</source>
        <translation>Nejdřív zvolte odpověď.</translation>
    </message>
    <message>
        <source>Step %1 of %2: %3. %4</source>
        <translation>Krok %1 z&#xa0;%2: %3. %4</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::LessonSession</name>
    <message>
        <source>Cannot open lesson</source>
        <translation>Lekci nelze otevřít</translation>
    </message>
    <message>
        <source>Open lesson</source>
        <translation>Otevřít lekci</translation>
    </message>
    <message>
        <source>%1 — step %2 — RigidLab</source>
        <translation>%1 – krok %2 – RigidLab</translation>
    </message>
    <message>
        <source>Export the step&apos;s plots into</source>
        <translation>Exportovat grafy kroku do složky</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export se nezdařil</translation>
    </message>
    <message>
        <source>Plots written to %1</source>
        <translation>Grafy zapsány do %1</translation>
    </message>
    <message>
        <source>RigidLab lessons (*.json *.rlesson)</source>
        <translation>Lekce RigidLabu (*.json *.rlesson)</translation>
    </message>
    <message>
        <source>Add a folder of lessons</source>
        <translation>Přidat složku s lekcemi</translation>
    </message>
    <message>
        <source>%1 fell off the stage at t = %2 s: the run paused. Play runs on.</source>
        <translation>Těleso „%1“ spadlo ze scény v&#xa0;čase t = %2 s: simulace se pozastavila. Tlačítko Spustit ji rozběhne dál.</translation>
    </message>
    <message>
        <source>This step&apos;s run ends at t = %1 s: the run paused. Play runs on.</source>
        <translation>Tento krok lekce končí v&#xa0;čase t = %1 s: simulace se pozastavila. Tlačítko Spustit ji rozběhne dál.</translation>
    </message>
    <message>
        <source>Every moving body has left the view at t = %1 s: the run paused. Play runs on.</source>
        <translation>Všechna pohybující se tělesa opustila zorné pole v&#xa0;čase t = %1 s: simulace se pozastavila. Tlačítko Spustit ji rozběhne dál.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::MainWindow</name>
    <message>
        <source>RigidLab</source>
        <translation>RigidLab</translation>
    </message>
    <message>
        <source>Controls</source>
        <translation>Ovládání</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <source>Momentum</source>
        <translation>Hybnost</translation>
    </message>
    <message>
        <source>Energy drift</source>
        <translation>Energetický drift</translation>
    </message>
    <message>
        <source>Drift</source>
        <translation>Drift</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Soubor</translation>
    </message>
    <message>
        <source>&amp;Open scene…</source>
        <translation>&amp;Otevřít scénu…</translation>
    </message>
    <message>
        <source>O&amp;pen lesson…</source>
        <translation>Otevřít &amp;lekci…</translation>
    </message>
    <message>
        <source>&amp;Lessons</source>
        <translation>Lek&amp;ce</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Otevřít &amp;nedávné</translation>
    </message>
    <message>
        <source>Shipped s&amp;cenes</source>
        <translation>&amp;Dodané scény</translation>
    </message>
    <message>
        <source>&amp;Export plot</source>
        <translation>&amp;Exportovat graf</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Ukončit</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>Si&amp;mulace</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Zobrazení</translation>
    </message>
    <message>
        <source>&amp;Presentation</source>
        <translation>&amp;Prezentace</translation>
    </message>
    <message>
        <source>Full screen, larger text and thicker lines for a projector (F11)</source>
        <translation>Celá obrazovka, větší písmo a&#xa0;silnější čáry pro projektor (F11)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Nápověda</translation>
    </message>
    <message>
        <source>Show or hide: %1</source>
        <translation>Zobrazit nebo skrýt: %1</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Jazyk</translation>
    </message>
    <message>
        <source>&amp;Velocity vectors</source>
        <translation>&amp;Vektory rychlosti</translation>
    </message>
    <message>
        <source>Velocities</source>
        <translation>Rychlosti</translation>
    </message>
    <message>
        <source>&amp;Contact points and normals</source>
        <translation>&amp;Kontaktní body a&#xa0;normály</translation>
    </message>
    <message>
        <source>Contacts</source>
        <translation>Kontakty</translation>
    </message>
    <message>
        <source>&amp;Bounding boxes</source>
        <translation>&amp;Ohraničující obdélníky</translation>
    </message>
    <message>
        <source>Boxes</source>
        <translation>Obdélníky</translation>
    </message>
    <message>
        <source>Centres of &amp;mass</source>
        <translation>&amp;Těžiště</translation>
    </message>
    <message>
        <source>Centres</source>
        <translation>Těžiště</translation>
    </message>
    <message>
        <source>Motion &amp;trails</source>
        <translation>&amp;Stopy pohybu</translation>
    </message>
    <message>
        <source>Trails</source>
        <translation>Stopy</translation>
    </message>
    <message>
        <source>&amp;Springs and joints</source>
        <translation>P&amp;ružiny a&#xa0;klouby</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Pružiny</translation>
    </message>
    <message>
        <source>Scene editor</source>
        <translation>Editor scény</translation>
    </message>
    <message>
        <source>RigidLab[*]</source>
        <translation>RigidLab[*]</translation>
    </message>
    <message>
        <source>%1[*] — RigidLab</source>
        <translation>%1[*] – RigidLab</translation>
    </message>
    <message>
        <source>%1 (%2)[*] — RigidLab</source>
        <translation>%1 (%2)[*] – RigidLab</translation>
    </message>
    <message>
        <source>&amp;New scene</source>
        <translation>Nová &amp;scéna</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>Uloži&amp;t</translation>
    </message>
    <message>
        <source>Save &amp;as…</source>
        <translation>Uložit j&amp;ako…</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>Úpr&amp;avy</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Zpět</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>Z&amp;novu</translation>
    </message>
    <message>
        <source>Scene as opened</source>
        <translation>Scéna, jak byla otevřena</translation>
    </message>
    <message>
        <source>Every edit since the scene was opened; click one to go back to it (the later ones stay, to redo)</source>
        <translation>Všechny úpravy od otevření scény; kliknutím na některou se k&#xa0;ní vrátíte (pozdější zůstanou pro opakování)</translation>
    </message>
    <message>
        <source>History of edits</source>
        <translation>Historie úprav</translation>
    </message>
    <message>
        <source>&amp;Controls…</source>
        <translation>&amp;Ovládání…</translation>
    </message>
    <message>
        <source>&amp;About RigidLab…</source>
        <translation>O&#xa0;&amp;aplikaci RigidLab…</translation>
    </message>
    <message>
        <source>&amp;Add a folder of lessons…</source>
        <translation>&amp;Přidat složku s lekcemi…</translation>
    </message>
    <message>
        <source>Edit lesson</source>
        <translation>Upravit lekci</translation>
    </message>
    <message>
        <source>Lessons (*.rlesson *.json)</source>
        <translation>Lekce (*.rlesson *.json)</translation>
    </message>
    <message>
        <source>Ne&amp;w lesson</source>
        <translation>No&amp;vá lekce</translation>
    </message>
    <message>
        <source>Edi&amp;t lesson…</source>
        <translation>Up&amp;ravit lekci…</translation>
    </message>
    <message>
        <source>Energy of the compared</source>
        <translation>Energie porovnávaných světů</translation>
    </message>
    <message>
        <source>Drift of the compared</source>
        <translation>Drift porovnávaných světů</translation>
    </message>
    <message>
        <source>Inspector</source>
        <translation>Inspektor</translation>
    </message>
    <message>
        <source>Separating axis test</source>
        <translation>Test oddělující osy</translation>
    </message>
    <message>
        <source>Bounces</source>
        <translation>Odrazy</translation>
    </message>
    <message>
        <source>Collision</source>
        <translation>Srážka</translation>
    </message>
    <message>
        <source>&amp;Back to the lesson editor</source>
        <translation>&amp;Zpět do editoru lekcí</translation>
    </message>
    <message>
        <source>Trying a lesson</source>
        <translation>Zkoušení lekce</translation>
    </message>
    <message>
        <source>Trying the lesson as a student sees it.</source>
        <translation>Zkoušíte lekci tak, jak ji vidí žák.</translation>
    </message>
    <message>
        <source>Back to the lesson editor (%1)</source>
        <translation>Zpět do editoru lekcí (%1)</translation>
    </message>
    <message>
        <source>S&amp;top listing a folder</source>
        <translation>Přestat &amp;zobrazovat složku</translation>
    </message>
    <message>
        <source>Its lessons are no longer listed; the folder and its files stay</source>
        <translation>Její lekce už nebudou v seznamu; složka i její soubory zůstanou</translation>
    </message>
    <message>
        <source>A lesson was not saved</source>
        <translation>Lekce nebyla uložena</translation>
    </message>
    <message>
        <source>RigidLab closed on %1 while a lesson was being written, before it was saved. Open what was kept?</source>
        <translation>RigidLab se zavřel (%1) uprostřed psaní lekce, dřív než byla uložena. Otevřít, co se zachovalo?</translation>
    </message>
    <message>
        <source>&amp;Open it</source>
        <translation>&amp;Otevřít ji</translation>
    </message>
    <message>
        <source>&amp;Delete it</source>
        <translation>&amp;Smazat ji</translation>
    </message>
    <message>
        <source>What was kept does not open: %1</source>
        <translation>Zachovanou lekci nelze otevřít: %1</translation>
    </message>
    <message>
        <source>Class res&amp;ults…</source>
        <translation>Výsledk&amp;y třídy…</translation>
    </message>
    <message>
        <source>Measurement</source>
        <translation>Měření</translation>
    </message>
    <message>
        <source>Pa&amp;nels</source>
        <translation>Pa&amp;nely</translation>
    </message>
    <message>
        <source>&amp;Lesson</source>
        <translation>&amp;Lekce</translation>
    </message>
    <message>
        <source>&amp;Controls</source>
        <translation>&amp;Ovládání</translation>
    </message>
    <message>
        <source>&amp;Inspector</source>
        <translation>&amp;Inspektor</translation>
    </message>
    <message>
        <source>&amp;Energy</source>
        <translation>&amp;Energie</translation>
    </message>
    <message>
        <source>&amp;Momentum</source>
        <translation>&amp;Hybnost</translation>
    </message>
    <message>
        <source>&amp;Drift</source>
        <translation>&amp;Drift</translation>
    </message>
    <message>
        <source>&amp;Axis test</source>
        <translation>&amp;Test os</translation>
    </message>
    <message>
        <source>&amp;Bounces</source>
        <translation>Odra&amp;zy</translation>
    </message>
    <message>
        <source>C&amp;ollision</source>
        <translation>&amp;Srážka</translation>
    </message>
    <message>
        <source>E&amp;rror vs run time</source>
        <translation>&amp;Chyba vs. doba běhu</translation>
    </message>
    <message>
        <source>Meas&amp;urement</source>
        <translation>&amp;Měření</translation>
    </message>
    <message>
        <source>&amp;Side by side</source>
        <translation>&amp;Vedle sebe</translation>
    </message>
    <message>
        <source>&amp;Properties</source>
        <translation>Vlast&amp;nosti</translation>
    </message>
    <message>
        <source>&amp;History</source>
        <translation>Histo&amp;rie</translation>
    </message>
    <message>
        <source>I&amp;nstruments</source>
        <translation>Měřidl&amp;a</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::MeasurementFit</name>
    <message>
        <source>Import a measurement of a position or velocity first.</source>
        <translation>Nejprve importujte měření polohy nebo rychlosti.</translation>
    </message>
    <message>
        <source>Tick a parameter to fit.</source>
        <translation>Zaškrtněte parametr, který se má určit.</translation>
    </message>
    <message>
        <source>%1 = %2%3 (95&#xa0;%)</source>
        <translation>%1 = %2%3 (95&#xa0;%)</translation>
    </message>
    <message numerus="yes">
        <source>Residual RMS: %1 over %n point(s)</source>
        <translation>
            <numerusform>Střední kvadratická hodnota reziduí: %1 (počet bodů: %n)</numerusform>
            <numerusform>Střední kvadratická hodnota reziduí: %1 (počet bodů: %n)</numerusform>
            <numerusform>Střední kvadratická hodnota reziduí: %1 (počet bodů: %n)</numerusform>
        </translation>
    </message>
    <message>
        <source>Fitted to the measurement in %1.</source>
        <translation>Určeno z&#xa0;měření v&#xa0;souboru %1.</translation>
    </message>
    <message>
        <source>Fit first: there are no fitted values to apply.</source>
        <translation>Nejprve parametry určete: zatím nejsou žádné hodnoty k&#xa0;použití.</translation>
    </message>
    <message>
        <source>Apply fitted values</source>
        <translation>Použití určených hodnot</translation>
    </message>
    <message>
        <source>There is no e from bounce times to apply.</source>
        <translation>Není žádné e z&#xa0;časů odrazů, které by šlo použít.</translation>
    </message>
    <message>
        <source>Apply e from the bounce times</source>
        <translation>Použití e z&#xa0;časů odrazů</translation>
    </message>
    <message>
        <source>From the bounce times alone (%3): e = %1 (95&#xa0;%). Each flight between bounces lasts e times the one before: %2.</source>
        <translation>Jen z&#xa0;časů odrazů (%3): e = %1 (95&#xa0;%). Každý let mezi odrazy trvá e‑násobek letu předchozího: %2.</translation>
    </message>
    <message>
        <source>Fit stopped: another measurement was imported. Fit again to fit the data compared now.</source>
        <translation>Určování z&#xa0;měření zastaveno: bylo importováno další měření. Spusťte ho znovu, ať se určí z&#xa0;dat, která se porovnávají teď.</translation>
    </message>
    <message>
        <source>Fit stopped: another body or quantity is compared. Fit again to fit the data compared now.</source>
        <translation>Určování z&#xa0;měření zastaveno: porovnává se jiné těleso nebo veličina. Spusťte ho znovu, ať se určí z&#xa0;dat, která se porovnávají teď.</translation>
    </message>
    <message>
        <source>Fit stopped: the scene changed. Fit again to fit the scene as it is now.</source>
        <translation>Určování z&#xa0;měření zastaveno: scéna se změnila. Spusťte ho znovu, ať se určí pro scénu, jak je teď.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::MeasurementImportDialog</name>
    <message>
        <source>not used</source>
        <translation>nepoužít</translation>
    </message>
    <message>
        <source>time t [s]</source>
        <translation>čas t [s]</translation>
    </message>
    <message>
        <source>position x [m]</source>
        <translation>poloha x [m]</translation>
    </message>
    <message>
        <source>position y (height) [m]</source>
        <translation>poloha y (výška) [m]</translation>
    </message>
    <message>
        <source>velocity vx [m/s]</source>
        <translation>rychlost vx [m/s]</translation>
    </message>
    <message>
        <source>velocity vy [m/s]</source>
        <translation>rychlost vy [m/s]</translation>
    </message>
    <message>
        <source>speed v [m/s]</source>
        <translation>velikost rychlosti v&#xa0;[m/s]</translation>
    </message>
    <message>
        <source>bounce times [s]</source>
        <translation>časy odrazů [s]</translation>
    </message>
    <message>
        <source>Import measurement</source>
        <translation>Import měření</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Soubor</translation>
    </message>
    <message>
        <source>What the file holds, or what is wrong with it</source>
        <translation>Co soubor obsahuje, nebo co je v&#xa0;něm špatně</translation>
    </message>
    <message>
        <source>Preview: the first points in the lab&apos;s units</source>
        <translation>Náhled: první body v&#xa0;jednotkách laboratoře</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importovat</translation>
    </message>
    <message>
        <source>Column</source>
        <translation>Sloupec</translation>
    </message>
    <message>
        <source>holds</source>
        <translation>obsahuje</translation>
    </message>
    <message>
        <source>column %1</source>
        <translation>sloupec %1</translation>
    </message>
    <message>
        <source>What column %1 holds</source>
        <translation>Co obsahuje sloupec %1</translation>
    </message>
    <message>
        <source>as the header says (else s)</source>
        <translation>podle hlavičky (jinak s)</translation>
    </message>
    <message>
        <source>Unit of the times in the file</source>
        <translation>Jednotka časů v&#xa0;souboru</translation>
    </message>
    <message>
        <source>as the header says (else m)</source>
        <translation>podle hlavičky (jinak m)</translation>
    </message>
    <message>
        <source>Unit of the lengths in the file</source>
        <translation>Jednotka délek v&#xa0;souboru</translation>
    </message>
    <message>
        <source>Time zero: the file&apos;s time at which the scene starts</source>
        <translation>Počátek času: čas v&#xa0;souboru, kdy scéna začíná</translation>
    </message>
    <message>
        <source>Origin x: where the scene&apos;s origin is in the file</source>
        <translation>Počátek x: kde v&#xa0;souboru leží počátek scény</translation>
    </message>
    <message>
        <source>Origin y: where the scene&apos;s origin is in the file</source>
        <translation>Počátek y: kde v&#xa0;souboru leží počátek scény</translation>
    </message>
    <message>
        <source>Time &amp;unit:</source>
        <translation>&amp;Jednotka času:</translation>
    </message>
    <message>
        <source>&amp;Length unit:</source>
        <translation>Jednotka &amp;délky:</translation>
    </message>
    <message>
        <source>Time &amp;zero (file time at the scene&apos;s start):</source>
        <translation>&amp;Počátek času (čas v&#xa0;souboru na začátku scény):</translation>
    </message>
    <message>
        <source>Scene origin in the file, &amp;x:</source>
        <translation>Počátek scény v&#xa0;souboru, &amp;x:</translation>
    </message>
    <message>
        <source>Scene origin in the file, &amp;y:</source>
        <translation>Počátek scény v&#xa0;souboru, &amp;y:</translation>
    </message>
    <message numerus="yes">
        <source>%n bounce time(s)</source>
        <translation>
            <numerusform>%n čas odrazu</numerusform>
            <numerusform>%n časy odrazů</numerusform>
            <numerusform>%n časů odrazů</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n bod</numerusform>
            <numerusform>%n body</numerusform>
            <numerusform>%n bodů</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n row(s) before time zero left out</source>
        <translation>
            <numerusform>%n řádek před počátkem času vynechán</numerusform>
            <numerusform>%n řádky před počátkem času vynechány</numerusform>
            <numerusform>%n řádků před počátkem času vynecháno</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::MeasurementPanel</name>
    <message>
        <source>Measurement imported</source>
        <translation>Importované měření</translation>
    </message>
    <message>
        <source>Body the measurement is compared with</source>
        <translation>Těleso, se kterým se měření porovnává</translation>
    </message>
    <message>
        <source>Measured quantity compared</source>
        <translation>Porovnávaná měřená veličina</translation>
    </message>
    <message>
        <source>&amp;Body:</source>
        <translation>Tě&amp;leso:</translation>
    </message>
    <message>
        <source>&amp;Quantity:</source>
        <translation>&amp;Veličina:</translation>
    </message>
    <message>
        <source>Measured and simulated</source>
        <translation>Naměřené a&#xa0;simulované</translation>
    </message>
    <message>
        <source>Plot: measured points and the simulated line</source>
        <translation>Graf: naměřené body a&#xa0;simulovaná čára</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>naměřené</translation>
    </message>
    <message>
        <source>simulated</source>
        <translation>simulované</translation>
    </message>
    <message>
        <source>Residuals: measured − simulated</source>
        <translation>Rezidua: naměřené − simulované</translation>
    </message>
    <message>
        <source>Plot: residuals, measured minus simulated</source>
        <translation>Graf: rezidua, naměřené minus simulované</translation>
    </message>
    <message>
        <source>measured − simulated</source>
        <translation>naměřené − simulované</translation>
    </message>
    <message>
        <source>Why the simulation cannot be compared</source>
        <translation>Proč simulaci nelze porovnat</translation>
    </message>
    <message>
        <source>Fit to the measurement</source>
        <translation>Určení z&#xa0;měření</translation>
    </message>
    <message>
        <source>F&amp;it</source>
        <translation>&amp;Určit z&#xa0;měření</translation>
    </message>
    <message>
        <source>Fit the ticked parameters to the measurement</source>
        <translation>Určit zaškrtnuté parametry z&#xa0;měření metodou nejmenších čtverců</translation>
    </message>
    <message>
        <source>&amp;Apply to scene</source>
        <translation>&amp;Použít ve scéně</translation>
    </message>
    <message>
        <source>Apply the fitted values to the scene (can be undone)</source>
        <translation>Použít určené hodnoty ve scéně (lze vrátit)</translation>
    </message>
    <message>
        <source>Fitted values</source>
        <translation>Určené hodnoty</translation>
    </message>
    <message>
        <source>e from the bounce times</source>
        <translation>e z&#xa0;časů odrazů</translation>
    </message>
    <message>
        <source>Apply &amp;e from the bounce times</source>
        <translation>Použít &amp;e z&#xa0;časů odrazů</translation>
    </message>
    <message>
        <source>Show &amp;residuals</source>
        <translation>Zobrazit &amp;rezidua</translation>
    </message>
    <message>
        <source>e (res&amp;titution)</source>
        <translation>&amp;e (restituce)</translation>
    </message>
    <message>
        <source>&amp;μ (friction)</source>
        <translation>&amp;μ (tření)</translation>
    </message>
    <message>
        <source>initial v&amp;x</source>
        <translation>počáteční v&amp;x</translation>
    </message>
    <message>
        <source>initial v&amp;y</source>
        <translation>počáteční v&amp;y</translation>
    </message>
    <message>
        <source>Fit the coefficient of restitution e</source>
        <translation>Určit z&#xa0;měření koeficient restituce e</translation>
    </message>
    <message>
        <source>Fit the friction coefficient μ</source>
        <translation>Určit z&#xa0;měření součinitel tření μ</translation>
    </message>
    <message>
        <source>Fit the initial velocity vx</source>
        <translation>Určit z&#xa0;měření počáteční rychlost vx</translation>
    </message>
    <message>
        <source>Fit the initial velocity vy</source>
        <translation>Určit z&#xa0;měření počáteční rychlost vy</translation>
    </message>
    <message>
        <source>No measurement yet: File › Import measurement… (%1), or drop a CSV file on the window.</source>
        <translation>Zatím žádné měření: Soubor › Importovat měření… (%1), nebo přetáhněte soubor CSV do okna.</translation>
    </message>
    <message>
        <source>Cancel fit</source>
        <translation>Zrušit určování</translation>
    </message>
    <message>
        <source>Cancel the fit that is running</source>
        <translation>Zrušit probíhající určování z&#xa0;měření</translation>
    </message>
    <message>
        <source>Fit running</source>
        <translation>Určování z&#xa0;měření probíhá</translation>
    </message>
    <message numerus="yes">
        <source>Fitting… %n run(s) of the model so far</source>
        <translation>
            <numerusform>Určuji… zatím %n běh modelu</numerusform>
            <numerusform>Určuji… zatím %n běhy modelu</numerusform>
            <numerusform>Určuji… zatím %n běhů modelu</numerusform>
        </translation>
    </message>
    <message>
        <source>Residuals</source>
        <translation>Rezidua</translation>
    </message>
    <message>
        <source>Comparison and fit</source>
        <translation>Porovnání a&#xa0;určení z&#xa0;měření</translation>
    </message>
    <message>
        <source>%1 (fit, residuals)</source>
        <translation>%1 (určení, rezidua)</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::MeasurementSession</name>
    <message>
        <source>&amp;Import measurement…</source>
        <translation>&amp;Importovat měření…</translation>
    </message>
    <message>
        <source>Read a measured time series (Tracker, phyphox or plain CSV) to compare the scene with and fit it to</source>
        <translation>Načíst naměřenou časovou řadu (CSV z&#xa0;Trackeru, z&#xa0;phyphoxu nebo prosté) k&#xa0;porovnání se scénou a&#xa0;k&#xa0;určení jejích parametrů</translation>
    </message>
    <message>
        <source>Import measurement</source>
        <translation>Import měření</translation>
    </message>
    <message>
        <source>Measurements (*.csv *.txt *.tsv);;All files (*)</source>
        <translation>Měření (*.csv *.txt *.tsv);;Všechny soubory (*)</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n point(s) of %2</source>
        <translation>
            <numerusform>%1: %2, %n bod</numerusform>
            <numerusform>%1: %2, %n body</numerusform>
            <numerusform>%1: %2, %n bodů</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::NumberField</name>
    <message>
        <source>%1 %2</source>
        <translation>%1&#xa0;%2</translation>
    </message>
    <message>
        <source>%1 must be a whole number from %2 to %3</source>
        <translation>%1 musí být celé číslo od %2 do %3</translation>
    </message>
    <message>
        <source>%1 must be from %2 to %3</source>
        <translation>%1 musí být od %2 do %3</translation>
    </message>
    <message>
        <source>“%1” is not a number: %2</source>
        <translation>„%1“ není číslo: %2</translation>
    </message>
    <message>
        <source>in %1</source>
        <comment>the unit a number field holds its value in</comment>
        <translation>v&#xa0;jednotkách %1</translation>
    </message>
    <message>
        <source>%1. %2</source>
        <comment>the unit, then the tooltip</comment>
        <translation>%1. %2</translation>
    </message>
    <message>
        <source>%1. It stays %2.</source>
        <comment>a refusal, then the value that stays in force</comment>
        <translation>%1. Zůstává %2.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::PlotExporter</name>
    <message>
        <source>Export plot</source>
        <translation>Exportovat graf</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export se nezdařil</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::PlotShelf</name>
    <message>
        <source>Plots</source>
        <translation>Grafy</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::PlotWidget</name>
    <message>
        <source>Export as PNG…</source>
        <translation>Exportovat do PNG…</translation>
    </message>
    <message>
        <source>Export as PDF…</source>
        <translation>Exportovat do PDF…</translation>
    </message>
    <message>
        <source>Export as SVG…</source>
        <translation>Exportovat do SVG…</translation>
    </message>
    <message>
        <source>Export data as CSV…</source>
        <translation>Exportovat data do CSV…</translation>
    </message>
    <message>
        <source>Follow</source>
        <translation>Sledovat</translation>
    </message>
    <message>
        <source>Last %1 s</source>
        <translation>Posledních %1&#xa0;s</translation>
    </message>
    <message>
        <source>Whole run</source>
        <translation>Celý běh</translation>
    </message>
    <message>
        <source>time t [s]</source>
        <translation>čas t [s]</translation>
    </message>
    <message>
        <source>Follow the run again (or double-click the plot)</source>
        <translation>Znovu sledovat běh (nebo dvakrát klikněte do grafu)</translation>
    </message>
    <message>
        <source>%1 (right axis)</source>
        <translation>%1 (pravá osa)</translation>
    </message>
    <message>
        <source>%1 (before going back)</source>
        <translation>%1 (před návratem)</translation>
    </message>
    <message>
        <source> ↑ off scale</source>
        <translation> ↑ mimo rozsah</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <source>energy E</source>
        <translation>energie E</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>kinetická</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potenciální</translation>
    </message>
    <message>
        <source>total</source>
        <translation>celková</translation>
    </message>
    <message>
        <source>dissipated</source>
        <translation>disipovaná</translation>
    </message>
    <message>
        <source>total + dissipated</source>
        <translation>celková + disip.</translation>
    </message>
    <message>
        <source>Momentum</source>
        <translation>Hybnost</translation>
    </message>
    <message>
        <source>p</source>
        <translation>p</translation>
    </message>
    <message>
        <source>L</source>
        <translation>L</translation>
    </message>
    <message>
        <source>Energy drift</source>
        <translation>Energetický drift</translation>
    </message>
    <message>
        <source>drift</source>
        <translation>drift</translation>
    </message>
    <message>
        <source>energy drift (numerical error)</source>
        <translation>energetický drift (numerická chyba)</translation>
    </message>
    <message>
        <source>Copy data shown</source>
        <translation>Kopírovat zobrazená data</translation>
    </message>
    <message>
        <source>position x</source>
        <translation>poloha x</translation>
    </message>
    <message>
        <source>position y</source>
        <translation>poloha y</translation>
    </message>
    <message>
        <source>velocity vx</source>
        <translation>rychlost vx</translation>
    </message>
    <message>
        <source>velocity vy</source>
        <translation>rychlost vy</translation>
    </message>
    <message>
        <source>speed |v|</source>
        <translation>velikost rychlosti |v|</translation>
    </message>
    <message>
        <source>acceleration |a|</source>
        <translation>velikost zrychlení |a|</translation>
    </message>
    <message>
        <source>angle θ in degrees</source>
        <translation>úhel θ ve stupních</translation>
    </message>
    <message>
        <source>angle θ in radians</source>
        <translation>úhel θ v radiánech</translation>
    </message>
    <message>
        <source>angular velocity ω</source>
        <translation>úhlová rychlost ω</translation>
    </message>
    <message>
        <source>kinetic energy E_k</source>
        <translation>kinetická energie E_k</translation>
    </message>
    <message>
        <source>momentum px</source>
        <translation>hybnost px</translation>
    </message>
    <message>
        <source>momentum py</source>
        <translation>hybnost py</translation>
    </message>
    <message>
        <source>angular momentum L</source>
        <translation>moment hybnosti L</translation>
    </message>
    <message>
        <source>Describe this plot…</source>
        <translation>Popsat tento graf…</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::QuestionArea</name>
    <message>
        <source>Questions</source>
        <translation>Otázky</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::QuestionEditor</name>
    <message>
        <source>Questions o&amp;f the step</source>
        <translation>&amp;Otázky kroku</translation>
    </message>
    <message>
        <source>Questions of the step</source>
        <translation>Otázky kroku</translation>
    </message>
    <message>
        <source>Add a &amp;measured question</source>
        <translation>Přidat měř&amp;enou otázku</translation>
    </message>
    <message>
        <source>Add a &amp;predict-first question</source>
        <translation>Přidat otázku s&#xa0;&amp;předpovědí</translation>
    </message>
    <message>
        <source>Remove &amp;question</source>
        <translation>Ode&amp;brat otázku</translation>
    </message>
    <message>
        <source>Predict first: the run waits until it is answered</source>
        <translation>Nejdřív předpověď: simulace počká, až žák odpoví</translation>
    </message>
    <message>
        <source>question</source>
        <translation>otázka</translation>
    </message>
    <message>
        <source>%1. Predict first: %2</source>
        <translation>%1. Nejdřív předpověď: %2</translation>
    </message>
    <message>
        <source>This step asks no question.</source>
        <translation>Tento krok se na nic neptá.</translation>
    </message>
    <message>
        <source>Kind of question</source>
        <translation>Druh otázky</translation>
    </message>
    <message>
        <source>&amp;Kind</source>
        <translation>&amp;Druh</translation>
    </message>
    <message>
        <source>A setting the student changes with the controls before the run this question measures (&quot;Set e = 0 and run again&quot;)</source>
        <translation>Nastavení, které žák změní v Ovládání před během, který tato otázka měří („Nastavte e = 0 a spusťte znovu“)</translation>
    </message>
    <message>
        <source>Stu&amp;dent sets first</source>
        <translation>Žák m&amp;usí nejdřív nastavit</translation>
    </message>
    <message>
        <source>Question (%1)</source>
        <translation>Otázka (%1)</translation>
    </message>
    <message>
        <source>Hint (%1)</source>
        <translation>Nápověda (%1)</translation>
    </message>
    <message>
        <source>What the student reads after a wrong first answer; empty: &quot;Try once more.&quot;</source>
        <translation>Co žák uvidí po první špatné odpovědi; prázdné: „Zkuste to ještě jednou.“</translation>
    </message>
    <message>
        <source>⚠ The lesson has a problem to fix first (see below): %1</source>
        <translation>⚠ V lekci je nejdřív třeba opravit problém (viz níže): %1</translation>
    </message>
    <message>
        <source>The right answer</source>
        <translation>Správný výsledek</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::QuestionSetEditor</name>
    <message>
        <source>Setting the student sets first</source>
        <translation>Nastavení, které žák nejdřív změní</translation>
    </message>
    <message>
        <source>nothing (the step&apos;s settings)</source>
        <translation>nic (nastavení kroku)</translation>
    </message>
    <message>
        <source>Value the student sets</source>
        <translation>Hodnota, kterou žák nastaví</translation>
    </message>
    <message>
        <source>on</source>
        <translation>zapnuto</translation>
    </message>
    <message>
        <source>off</source>
        <translation>vypnuto</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::SatPanel</name>
    <message>
        <source>◀ Previous</source>
        <translation>◀ Předchozí</translation>
    </message>
    <message>
        <source>Next ▶</source>
        <translation>Další ▶</translation>
    </message>
    <message>
        <source>All</source>
        <translation>Vše</translation>
    </message>
    <message>
        <source>Show the previous axis tested</source>
        <translation>Zobrazit předchozí testovanou osu</translation>
    </message>
    <message>
        <source>Test the next axis</source>
        <translation>Otestovat další osu</translation>
    </message>
    <message>
        <source>Test every axis, up to the verdict</source>
        <translation>Otestovat všechny osy až k&#xa0;výsledku</translation>
    </message>
    <message>
        <source>axis</source>
        <translation>osa</translation>
    </message>
    <message>
        <source>interval
[m]</source>
        <translation>interval
[m]</translation>
    </message>
    <message>
        <source>overlap
[m]</source>
        <translation>překryv
[m]</translation>
    </message>
    <message>
        <source>The axis is the normal of this edge: polygon A or B, then the edge&apos;s number.</source>
        <translation>Osa je normála této hrany: mnohoúhelník A&#xa0;nebo B, pak číslo hrany.</translation>
    </message>
    <message>
        <source>The interval each polygon covers when projected on the axis (A above, B below).</source>
        <translation>Interval, který každý mnohoúhelník pokryje po promítnutí na osu (A&#xa0;nahoře, B dole).</translation>
    </message>
    <message>
        <source>How far the intervals overlap, in metres; &quot;gap&quot; when they do not, and the axis separates. Below it, what the axis means for the test.</source>
        <translation>Jak moc se intervaly překrývají, v&#xa0;metrech; „mezera“, když se nepřekrývají a&#xa0;osa je odděluje. Pod tím, co osa znamená pro test.</translation>
    </message>
    <message>
        <source>Export as CSV…</source>
        <translation>Exportovat do CSV…</translation>
    </message>
    <message>
        <source>separating_axes</source>
        <translation>oddelujici_osy</translation>
    </message>
    <message>
        <source>Drag a polygon to move it; Q and E turn the selected one.</source>
        <translation>Mnohoúhelník posunete tažením; Q a&#xa0;E otáčejí vybraným.</translation>
    </message>
    <message>
        <source>gap %1</source>
        <translation>mezera %1</translation>
    </message>
    <message>
        <source>separates</source>
        <translation>odděluje</translation>
    </message>
    <message>
        <source>least overlap</source>
        <translation>nejmenší překryv</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <comment>polygon (A or B), edge number</comment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>A %1 … %2
B %3 … %4</source>
        <translation>A&#xa0;%1 … %2
B&#xa0;%3 … %4</translation>
    </message>
    <message>
        <source>Axis %1: the normal of edge %2 of %3. On it, %4 covers [%5, %6] m and %7 covers [%8, %9] m.</source>
        <translation>Osa %1: normála hrany %2 tělesa %3. Na ní %4 pokrývá [%5; %6]&#xa0;m a&#xa0;%7 pokrývá [%8; %9]&#xa0;m.</translation>
    </message>
    <message>
        <source>They are %1 m apart: a gap.</source>
        <translation>Jsou od sebe %1&#xa0;m: mezera.</translation>
    </message>
    <message>
        <source>They overlap by %1 m.</source>
        <translation>Překrývají se o&#xa0;%1&#xa0;m.</translation>
    </message>
    <message>
        <source>This axis separates the polygons: they cannot touch, and the test stops here (no collision).</source>
        <translation>Tato osa mnohoúhelníky odděluje: nemohou se dotýkat a&#xa0;test tady končí (žádná srážka).</translation>
    </message>
    <message>
        <source>The least overlap of all axes: this axis is the contact normal, and the overlap is the depth.</source>
        <translation>Nejmenší překryv ze všech os: tato osa je normála kontaktu a&#xa0;překryv je hloubka průniku.</translation>
    </message>
    <message>
        <source>No pair of polygons to test.</source>
        <translation>Žádná dvojice mnohoúhelníků k&#xa0;testování.</translation>
    </message>
    <message>
        <source>Axis %1 of %2 tested so far: no separating axis yet.</source>
        <translation>Otestována osa %1 z&#xa0;%2: oddělující osa zatím nenalezena.</translation>
    </message>
    <message>
        <source>Separated: axis %1 has a gap, so the test stops there.</source>
        <translation>Odděleno: na ose %1 je mezera, a&#xa0;tak tam test končí.</translation>
    </message>
    <message>
        <source>Overlapping: no axis separates them.</source>
        <translation>Překrývají se: žádná osa je neodděluje.</translation>
    </message>
    <message>
        <source>The test needed %1 of at most %2 axes (one per edge, %3 + %4), each projecting all %2 vertices: %5 projections, against the paper&apos;s worst case of (k₁ + k₂)² = %6.</source>
        <translation>Test potřeboval %1 z&#xa0;nejvýše %2&#xa0;os (jedna na hranu, %3 + %4) a&#xa0;na každé promítl všech %2&#xa0;vrcholů: celkem %5&#xa0;projekcí, oproti nejhoršímu případu podle původního článku (k₁ + k₂)² = %6.</translation>
    </message>
    <message>
        <source>Least overlap on axis %1: normal (%2, %3) from A to B, depth %4 m, %5 contact point(s) from clipping.</source>
        <translation>Nejmenší překryv na ose %1: normála (%2; %3) od A&#xa0;k&#xa0;B, hloubka %4&#xa0;m, kontaktní body z&#xa0;ořezání: %5.</translation>
    </message>
    <message>
        <source>Axes tested</source>
        <translation>Testované osy</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::SceneNarrator</name>
    <message>
        <source>%1 and %2 touch.</source>
        <translation>%1 a&#xa0;%2 se dotýkají.</translation>
    </message>
    <message>
        <source>Everything has come to rest.</source>
        <translation>Všechno se zastavilo.</translation>
    </message>
    <message>
        <source>The simulation diverged and stopped.</source>
        <translation>Výpočet se rozběhl a&#xa0;simulace se zastavila.</translation>
    </message>
    <message>
        <source>Running.</source>
        <translation>Běží.</translation>
    </message>
    <message>
        <source>Paused at %1.</source>
        <translation>Pozastaveno v&#xa0;čase %1.</translation>
    </message>
    <message>
        <source>%1: position %2, velocity %3.</source>
        <translation>%1: poloha %2, rychlost %3.</translation>
    </message>
    <message>
        <source>%1, speed %2.</source>
        <translation>%1, velikost rychlosti %2.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::SceneProperties</name>
    <message>
        <source>Body</source>
        <translation>Těleso</translation>
    </message>
    <message>
        <source>Set %1</source>
        <translation>Nastavit: %1</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Pružina</translation>
    </message>
    <message>
        <source>World</source>
        <translation>Svět</translation>
    </message>
    <message>
        <source>Default colour</source>
        <translation>Výchozí barva</translation>
    </message>
    <message>
        <source>Set colour</source>
        <translation>Nastavit barvu</translation>
    </message>
    <message>
        <source>Set %1 of %2</source>
        <translation>Nastavit %1 tělesa %2</translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>Přejmenovat %1 na %2</translation>
    </message>
    <message>
        <source>Set type of %1</source>
        <translation>Nastavit typ tělesa %1</translation>
    </message>
    <message>
        <source>Set %1 of spring %2</source>
        <translation>Nastavit %1 pružiny %2</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scéna</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::SimulationController</name>
    <message>
        <source>dt = %1 s</source>
        <translation>dt = %1&#xa0;s</translation>
    </message>
    <message numerus="yes">
        <source>%n iteration(s)</source>
        <translation>
            <numerusform>%n iterace</numerusform>
            <numerusform>%n iterace</numerusform>
            <numerusform>%n iterací</numerusform>
        </translation>
    </message>
    <message>
        <source>e = %1</source>
        <translation>e = %1</translation>
    </message>
    <message>
        <source>μ = %1</source>
        <translation>μ = %1</translation>
    </message>
    <message>
        <source>gravity on</source>
        <translation>tíhová síla zapnuta</translation>
    </message>
    <message>
        <source>gravity off</source>
        <translation>tíhová síla vypnuta</translation>
    </message>
    <message>
        <source>m = %1 kg</source>
        <translation>m = %1&#xa0;kg</translation>
    </message>
    <message>
        <source>v = (%1; %2) m/s</source>
        <translation>v = (%1; %2)&#xa0;m/s</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::StatusLine</name>
    <message>
        <source>slower than real time</source>
        <translation>pomaleji než v&#xa0;reálném čase</translation>
    </message>
    <message>
        <source>Status &amp;details (steps/s, stage timings)</source>
        <translation>Po&amp;drobnosti stavu (kroky/s, časy fází)</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Časová osa</translation>
    </message>
    <message>
        <source>Time travel: drag to go back to any moment, then play to go on (or change a setting to branch)</source>
        <translation>Cesta časem: tažením se vraťte do libovolného okamžiku a&#xa0;spuštěním pokračujte (nebo změnou nastavení začněte novou větev)</translation>
    </message>
    <message>
        <source> Timeline </source>
        <translation> Časová osa </translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1&#xa0;s</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>pozastaveno</translation>
    </message>
    <message>
        <source>%1 × real time</source>
        <translation>%1&#xa0;× reálný čas</translation>
    </message>
    <message>
        <source>running</source>
        <translation>běží</translation>
    </message>
    <message>
        <source> · dissipated %1 J</source>
        <translation> · disipovaná energie %1&#xa0;J</translation>
    </message>
    <message>
        <source> · dissipated by contacts, friction, drag and dampers %1 J</source>
        <translation> · energie odebraná kontakty, třením, odporem prostředí a&#xa0;tlumiči %1&#xa0;J</translation>
    </message>
    <message numerus="yes">
        <source> · %1 error estimate %2 (%Ln substep(s))</source>
        <translation>
            <numerusform> · %1: odhad chyby %2 (%Ln podkrok)</numerusform>
            <numerusform> · %1: odhad chyby %2 (%Ln podkroky)</numerusform>
            <numerusform> · %1: odhad chyby %2 (%Ln podkroků)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>last step %1 ms: %2</source>
        <translation>poslední krok %1&#xa0;ms: %2</translation>
    </message>
    <message>
        <source>%1 steps/s · frame %2 ms (physics %3 ms) · %4</source>
        <translation>%1&#xa0;kroků/s · snímek %2&#xa0;ms (fyzika %3&#xa0;ms) · %4</translation>
    </message>
    <message>
        <source> step %1 of %2 · t = %3 s</source>
        <translation> krok %1 z&#xa0;%2 · t = %3&#xa0;s</translation>
    </message>
    <message>
        <source>Contact solver: %1</source>
        <translation>Řešič kontaktů: %1</translation>
    </message>
    <message>
        <source>A frame&apos;s physics takes longer than the frame has: the clock leaves out the time it cannot catch up with, so the run goes slower than real time instead of falling further behind.</source>
        <translation>Fyzika jednoho snímku trvá déle, než kolik snímek má času: hodiny vynechají čas, který nestihnou dohnat, a&#xa0;simulace tak běží pomaleji než v&#xa0;reálném čase, místo aby se opožďovala čím dál víc.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::StepChecks</name>
    <message>
        <source>The step&apos;s simulation, run with its settings, %1.</source>
        <translation>Simulace kroku spuštěná s jeho nastavením %1.</translation>
    </message>
    <message>
        <source>Question %1: the integrators a student may choose measure from %2 to %3 %4, wider than the answers judged right (%5 to %6 %4): lock the integrator (Shown and locked) or widen the tolerance.</source>
        <translation>Otázka %1: integrátory, které si žák může zvolit, naměří od %2 do %3 %4, víc, než kolik pokrývají odpovědi uznané za správné (%5 až %6 %4): zamkněte integrátor (Zobrazeno a zamčeno), nebo zvětšete toleranci.</translation>
    </message>
    <message>
        <source>%1 falls off the stage at t = %2 s, and the run stops there: give the step an end time before it, or more ground.</source>
        <translation>Těleso „%1“ spadne ze scény v&#xa0;čase t = %2 s a simulace se tam zastaví: dejte kroku dřívější čas konce, nebo delší podložku.</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::StepSettingsEditor</name>
    <message>
        <source>What the step shows and lets the student change</source>
        <translation>Co krok ukazuje a co smí žák měnit</translation>
    </message>
    <message>
        <source>Plots shown</source>
        <translation>Zobrazené grafy</translation>
    </message>
    <message>
        <source>Panels shown</source>
        <translation>Zobrazené panely</translation>
    </message>
    <message>
        <source>The student may change (unticked: locked)</source>
        <translation>Žák smí měnit (nezaškrtnuté: zamčeno)</translation>
    </message>
    <message>
        <source>Plots exported at</source>
        <translation>Grafy se exportují v čase</translation>
    </message>
    <message>
        <source>The simulated time at which the step&apos;s plots are exported, 0.1 to 600 s</source>
        <translation>Simulovaný čas, v němž se exportují grafy kroku, 0,1 až 600&#xa0;s</translation>
    </message>
    <message>
        <source>export time</source>
        <translation>čas exportu</translation>
    </message>
    <message>
        <source>what the student may change</source>
        <translation>co smí žák měnit</translation>
    </message>
    <message>
        <source>plots shown</source>
        <translation>zobrazené grafy</translation>
    </message>
    <message>
        <source>panels shown</source>
        <translation>zobrazené panely</translation>
    </message>
    <message>
        <source>runs on</source>
        <translation>běží dál</translation>
    </message>
    <message>
        <source>The run stops at</source>
        <translation>Běh se zastaví v čase</translation>
    </message>
    <message>
        <source>The simulated time at which the step&apos;s run stops, so that nothing runs off the stage; 0: it runs on</source>
        <translation>Simulovaný čas, v němž se běh kroku zastaví, aby nic neodjelo ze scény; 0: běží dál</translation>
    </message>
    <message>
        <source>The run st&amp;ops at</source>
        <translation>Běh se zas&amp;taví v čase</translation>
    </message>
    <message>
        <source>end of the run</source>
        <translation>konec běhu</translation>
    </message>
    <message>
        <source>Wait for &amp;Play: the step opens paused, so that the class reads and predicts first</source>
        <translation>Čekat na &amp;spuštění: krok se otevře zastavený, aby třída nejdřív četla a předpovídala</translation>
    </message>
    <message>
        <source>wait for Play</source>
        <translation>čekat na spuštění</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::StepText</name>
    <message>
        <source>Scroll the step&apos;s text sideways</source>
        <translation>Posouvat text kroku do stran</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::WindowActions</name>
    <message>
        <source>Simulation</source>
        <translation>Simulace</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Spustit</translation>
    </message>
    <message>
        <source>Play or pause (%1)</source>
        <translation>Spustit nebo pozastavit (%1)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Krok</translation>
    </message>
    <message>
        <source>One step forward (%1)</source>
        <translation>O&#xa0;jeden krok vpřed (%1)</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zpět</translation>
    </message>
    <message>
        <source>One step back in time (%1)</source>
        <translation>O&#xa0;jeden krok zpět v&#xa0;čase (%1)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Na začátek</translation>
    </message>
    <message>
        <source>Back to the start of the scene (%1)</source>
        <translation>Zpět na začátek scény (%1)</translation>
    </message>
    <message>
        <source>Zoom to show every body (%1)</source>
        <translation>Přiblížit tak, aby byla vidět všechna tělesa (%1)</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastavit</translation>
    </message>
    <message>
        <source>Turn selected body left</source>
        <translation>Otočit vybrané těleso doleva</translation>
    </message>
    <message>
        <source>Turn selected body right</source>
        <translation>Otočit vybrané těleso doprava</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>The world does not step in Edit mode: leave it (%1) or press Play to run the scene as edited</source>
        <translation>V editoru svět nekrokuje: vypněte ho (%1) nebo stiskněte Spustit a scéna poběží tak, jak je upravená</translation>
    </message>
    <message>
        <source>&amp;Fit scene</source>
        <translation>&amp;Celá scéna</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::WindowDocuments</name>
    <message>
        <source>Cannot open scene</source>
        <translation>Scénu nelze otevřít</translation>
    </message>
    <message>
        <source>%1 was not opened: the edited scene stays.</source>
        <translation>%1 nebyl otevřen: upravovaná scéna zůstává.</translation>
    </message>
    <message>
        <source>RigidLab scenes (*.json)</source>
        <translation>Scény RigidLabu (*.json)</translation>
    </message>
    <message>
        <source>New scene</source>
        <translation>Nová scéna</translation>
    </message>
    <message>
        <source>Edits made before the language changed</source>
        <translation>Úpravy provedené před změnou jazyka</translation>
    </message>
    <message>
        <source>%1 comes with RigidLab and is not overwritten: save your version under a name of its own.</source>
        <translation>%1 je dodáván s RigidLabem a nepřepisuje se: uložte svou verzi pod vlastním jménem.</translation>
    </message>
    <message>
        <source>Save scene as</source>
        <translation>Uložit scénu jako</translation>
    </message>
    <message>
        <source>%1 comes with RigidLab and is not overwritten. Choose another name, or a folder of your own (your scenes are in %2).</source>
        <translation>%1 je dodáván s RigidLabem a nepřepisuje se. Zvolte jiné jméno nebo vlastní složku (vaše scény jsou v %2).</translation>
    </message>
    <message>
        <source>Scene not saved</source>
        <translation>Scéna nebyla uložena</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Uloženo: %1</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Neuložené změny</translation>
    </message>
    <message>
        <source>The scene “%1” has changes that are not saved.</source>
        <translation>Scéna „%1“ má neuložené změny.</translation>
    </message>
    <message>
        <source>Save them before going on?</source>
        <translation>Uložit je před pokračováním?</translation>
    </message>
    <message>
        <source>&amp;Your own scenes</source>
        <translation>&amp;Vlastní scény</translation>
    </message>
    <message>
        <source>Open scene or lesson</source>
        <translation>Otevřít scénu nebo lekci</translation>
    </message>
    <message>
        <source>RigidLab scenes and lessons (*.json *.rlesson);;Lessons in one file (*.rlesson)</source>
        <translation>Scény a lekce RigidLabu (*.json *.rlesson);;Lekce v&#xa0;jednom souboru (*.rlesson)</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::WindowKeyboard</name>
    <message>
        <source>Next lesson step</source>
        <translation>Další krok lekce</translation>
    </message>
    <message>
        <source>Previous lesson step</source>
        <translation>Předchozí krok lekce</translation>
    </message>
    <message>
        <source>Focus the scene</source>
        <translation>Fokus na scénu</translation>
    </message>
    <message>
        <source>Select next body</source>
        <translation>Vybrat další těleso</translation>
    </message>
    <message>
        <source>Select previous body</source>
        <translation>Vybrat předchozí těleso</translation>
    </message>
    <message>
        <source>Letters, Space and arrows alone act as shortcuts; off, only keys with Ctrl, Alt or F-keys do</source>
        <translation>Písmena, mezerník a&#xa0;šipky samy fungují jako zkratky; vypnuto fungují jen klávesy s&#xa0;Ctrl, Alt nebo klávesy F</translation>
    </message>
    <message>
        <source>Focus the toolbar</source>
        <translation>Fokus na panel nástrojů</translation>
    </message>
    <message>
        <source>Panels, menus, lists and tooltips appear at once, without animation</source>
        <translation>Panely, nabídky, seznamy a tipy se objeví hned, bez animace</translation>
    </message>
    <message>
        <source>Single-&amp;key shortcuts</source>
        <translation>Jednoklávesové &amp;zkratky</translation>
    </message>
    <message>
        <source>&amp;Reduced motion</source>
        <translation>O&amp;mezit pohyb</translation>
    </message>
    <message>
        <source>On the scene, in a lesson step that asks something: go to its answer</source>
        <translation>Na scéně, v&#xa0;kroku lekce, který se na něco ptá: přejít na jeho odpověď</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::WorkPrecisionPlot</name>
    <message>
        <source>Error vs run time</source>
        <translation>Chyba vs. doba běhu</translation>
    </message>
    <message>
        <source>CPU time of the run [s]</source>
        <translation>čas CPU běhu [s]</translation>
    </message>
    <message>
        <source>final position error</source>
        <translation>chyba koncové polohy</translation>
    </message>
    <message>
        <source>Error vs run time: %1</source>
        <translation>Chyba vs. doba běhu: %1</translation>
    </message>
    <message>
        <source>p = %1</source>
        <translation>p = %1</translation>
    </message>
    <message>
        <source>order: needs a second run</source>
        <translation>řád: je potřeba druhý běh</translation>
    </message>
    <message>
        <source>no order: error at round-off</source>
        <translation>řád nelze určit: chyba na úrovni zaokrouhlení</translation>
    </message>
    <message>
        <source>no order: error too large</source>
        <translation>řád nelze určit: chyba je příliš velká</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::WorldView</name>
    <message>
        <source>%1 — blew up at t = %2 s</source>
        <translation>%1 – výpočet „vybuchl“ v&#xa0;čase t = %2&#xa0;s</translation>
    </message>
    <message>
        <source>%1 — stopped at t = %2 s: %3</source>
        <translation>%1 – zastaveno v&#xa0;čase t = %2&#xa0;s: %3</translation>
    </message>
    <message>
        <source>%1 (solid)</source>
        <translation>%1 (plná tělesa)</translation>
    </message>
    <message>
        <source>%1 (outline)</source>
        <translation>%1 (obrysy)</translation>
    </message>
    <message>
        <source>%1 (solid): %2</source>
        <translation>%1 (plná tělesa): %2</translation>
    </message>
    <message>
        <source>%1 (outline): %2</source>
        <translation>%1 (obrysy): %2</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1&#xa0;m</translation>
    </message>
    <message>
        <source>%1 cm</source>
        <translation>%1&#xa0;cm</translation>
    </message>
    <message>
        <source>%1 stopped</source>
        <translation>%1: zastaveno</translation>
    </message>
    <message>
        <source>Scene drawing</source>
        <translation>Kresba scény</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::displayNames</name>
    <message>
        <source>Explicit Euler</source>
        <translation>Explicitní Euler</translation>
    </message>
    <message>
        <source>Symplectic Euler</source>
        <translation>Symplektický Euler</translation>
    </message>
    <message>
        <source>Velocity Verlet</source>
        <translation>Rychlostní Verlet</translation>
    </message>
    <message>
        <source>Runge–Kutta 4</source>
        <translation>Runge–Kutta 4</translation>
    </message>
    <message>
        <source>Dormand–Prince 5(4), adaptive</source>
        <translation>Dormand–Prince 5(4), adaptivní</translation>
    </message>
    <message>
        <source>Implicit midpoint</source>
        <translation>Implicitní střední bod</translation>
    </message>
    <message>
        <source>The paper&apos;s impulse</source>
        <translation>Kontakt po kontaktu</translation>
    </message>
    <message>
        <source>Sequential impulse</source>
        <translation>Postupné impulsy</translation>
    </message>
    <message>
        <source>broad phase</source>
        <translation>hrubá fáze</translation>
    </message>
    <message>
        <source>narrow phase</source>
        <translation>jemná fáze</translation>
    </message>
    <message>
        <source>islands</source>
        <translation>ostrovy</translation>
    </message>
    <message>
        <source>forces</source>
        <translation>síly</translation>
    </message>
    <message>
        <source>integration</source>
        <translation>integrace</translation>
    </message>
    <message>
        <source>contact solve</source>
        <translation>řešení kontaktů</translation>
    </message>
    <message>
        <source>sleep</source>
        <translation>uspávání</translation>
    </message>
    <message>
        <source>diagnostics</source>
        <translation>diagnostika</translation>
    </message>
    <message>
        <source>Soft step (substepping)</source>
        <translation>Měkký krok (podkroky)</translation>
    </message>
</context>
<context>
    <name>rigidlab::ui::exportPlot</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>nelze zapsat %1: %2</translation>
    </message>
    <message>
        <source>not enough memory for a %1 x %2 px image</source>
        <translation>nedostatek paměti pro obrázek %1&#xa0;× %2&#xa0;px</translation>
    </message>
    <message>
        <source>could not start drawing the PDF</source>
        <translation>nelze začít kreslit PDF</translation>
    </message>
    <message>
        <source>could not start drawing the SVG</source>
        <translation>nelze začít kreslit SVG</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Obrázek PNG (*.png)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>Dokument PDF (*.pdf)</translation>
    </message>
    <message>
        <source>SVG drawing (*.svg)</source>
        <translation>Kresba SVG (*.svg)</translation>
    </message>
    <message>
        <source>CSV table (*.csv)</source>
        <translation>Tabulka CSV (*.csv)</translation>
    </message>
    <message>
        <source>cannot export: no file name given</source>
        <translation>nelze exportovat: chybí název souboru</translation>
    </message>
    <message>
        <source>empty picture size</source>
        <translation>prázdná velikost obrázku</translation>
    </message>
    <message>
        <source>comma</source>
        <translation>čárka</translation>
    </message>
    <message>
        <source>decimal comma</source>
        <translation>desetinná čárka</translation>
    </message>
    <message>
        <source>decimal point</source>
        <translation>desetinná tečka</translation>
    </message>
    <message>
        <source>CSV for a spreadsheet (%1, %2) (*.csv)</source>
        <translation>CSV pro tabulkový procesor (%1, %2) (*.csv)</translation>
    </message>
    <message>
        <source>CSV plain, for scripts (%1, %2) (*.csv)</source>
        <translation>CSV prosté, pro skripty (%1, %2) (*.csv)</translation>
    </message>
    <message>
        <source>this build of RigidLab cannot write SVG</source>
        <translation>toto sestavení RigidLabu neumí zapisovat SVG</translation>
    </message>
</context>
</TS>
