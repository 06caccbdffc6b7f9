<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>AttributeColors</name>
    <message>
        <source>Light per internode</source>
        <translation>Licht pro Internodium</translation>
    </message>
    <message>
        <source>Vigour (log scale)</source>
        <translation>Wuchskraft (logarithmisch)</translation>
    </message>
    <message>
        <source>Age in cycles</source>
        <translation>Alter in Zyklen</translation>
    </message>
    <message>
        <source>Branch order</source>
        <translation>Astordnung</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materialien</translation>
    </message>
    <message>
        <source>%1: not available for this tree</source>
        <translation>%1: für diesen Baum nicht verfügbar</translation>
    </message>
    <message>
        <source>%1: 0 (blue) – %2 (yellow)</source>
        <translation>%1: 0 (blau) – %2 (gelb)</translation>
    </message>
    <message>
        <source>; red: %1 internodes in branches below the shedding threshold %2, shed at the next cycle</source>
        <translation>; rot: %1 Internodien in Ästen unter der Abwurfschwelle %2, im nächsten Zyklus abgeworfen</translation>
    </message>
    <message>
        <source>; no branch is below the shedding threshold %1</source>
        <translation>; kein Ast liegt unter der Abwurfschwelle %1</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>%1: the species&apos; output node produced no mesh</source>
        <translation>%1: Der Ausgabeknoten der Art hat kein Netz erzeugt</translation>
    </message>
    <message>
        <source>%1: out of memory while generating the tree</source>
        <translation>%1: Nicht genug Speicher beim Erzeugen des Baums</translation>
    </message>
    <message>
        <source>%1: unexpected error: %2</source>
        <translation>%1: Unerwarteter Fehler: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1 (%n trees)</source>
        <translation>
            <numerusform>%1 (%n Baum)</numerusform>
            <numerusform>%1 (%n Bäume)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: the project has no trees and no obstacles</source>
        <translation>%1: Das Projekt hat weder Bäume noch Hindernisse</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Sylva, the procedural tree editor.</source>
        <translation>Sylva, der prozedurale Baumeditor.</translation>
    </message>
    <message>
        <source>Render the viewport to &lt;file&gt; (PNG) and exit.</source>
        <translation>Die Ansicht als &lt;file&gt; (PNG) speichern und beenden.</translation>
    </message>
    <message>
        <source>Viewport size in pixels, e.g. 1024x768.</source>
        <translation>Größe der Ansicht in Pixeln, z. B. 1024x768.</translation>
    </message>
    <message>
        <source>--size expects WxH between 16 and 8192, got &apos;%1&apos;</source>
        <translation>--size erwartet BxH zwischen 16 und 8192, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Colour the tree by &lt;mode&gt;: material, light, vigour, age or order.</source>
        <translation>Den Baum nach &lt;mode&gt; einfärben: material, light, vigour, age oder order.</translation>
    </message>
    <message>
        <source>--color-by expects material, light, vigour, age or order, got &apos;%1&apos;</source>
        <translation>--color-by erwartet material, light, vigour, age oder order, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Species or project (.sylva) to open (default: the ternary tree).</source>
        <translation>Zu öffnende Art oder Projekt (.sylva) (Standard: der ternäre Baum).</translation>
    </message>
    <message>
        <source>expected at most one species or project file</source>
        <translation>höchstens eine Art- oder Projektdatei erwartet</translation>
    </message>
</context>
<context>
    <name>sylva::ui::MainWindow</name>
    <message>
        <source>Sylva</source>
        <translation>Sylva</translation>
    </message>
    <message>
        <source>Tree</source>
        <translation>Baum</translation>
    </message>
    <message>
        <source>Generating: %1</source>
        <translation>Erzeuge: %1</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation>&amp;Neu laden</translation>
    </message>
    <message>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <source>Save &amp;screenshot…</source>
        <translation>&amp;Bildschirmfoto speichern…</translation>
    </message>
    <message>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Vorlagen</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Frame tree</source>
        <translation>Baum ein&amp;passen</translation>
    </message>
    <message>
        <source>Show &amp;grid</source>
        <translation>&amp;Gitter anzeigen</translation>
    </message>
    <message>
        <source>No presets folder found (set SYLVA_PRESETS_DIR)</source>
        <translation>Kein Vorlagenordner gefunden (SYLVA_PRESETS_DIR setzen)</translation>
    </message>
    <message>
        <source>No presets in %1</source>
        <translation>Keine Vorlagen in %1</translation>
    </message>
    <message>
        <source>Generating %1…</source>
        <translation>Erzeuge %1…</translation>
    </message>
    <message>
        <source>No presets folder found: set SYLVA_PRESETS_DIR or open a species file with File ▸ Open species…</source>
        <translation>Kein Vorlagenordner gefunden: SYLVA_PRESETS_DIR setzen oder eine Artdatei mit Datei ▸ Art öffnen… laden</translation>
    </message>
    <message>
        <source>%1 — Sylva</source>
        <translation>%1 — Sylva</translation>
    </message>
    <message>
        <source>Generated %1 in %2 ms</source>
        <translation>%1 in %2 ms erzeugt</translation>
    </message>
    <message>
        <source>Could not read the viewport&apos;s image (no OpenGL context).</source>
        <translation>Das Bild der Ansicht konnte nicht gelesen werden (kein OpenGL-Kontext).</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>%1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>Bildschirmfoto speichern</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.bmp)</source>
        <translation>Bilder (*.png *.jpg *.bmp)</translation>
    </message>
    <message>
        <source>&amp;Colour by</source>
        <translation>&amp;Einfärben nach</translation>
    </message>
    <message>
        <source>&amp;Material</source>
        <translation>&amp;Material</translation>
    </message>
    <message>
        <source>&amp;Light (per internode)</source>
        <translation>&amp;Licht (pro Internodium)</translation>
    </message>
    <message>
        <source>&amp;Vigour</source>
        <translation>&amp;Wuchskraft</translation>
    </message>
    <message>
        <source>&amp;Age</source>
        <translation>&amp;Alter</translation>
    </message>
    <message>
        <source>Branch &amp;order</source>
        <translation>Ast&amp;ordnung</translation>
    </message>
    <message>
        <source>&amp;Open species or project…</source>
        <translation>Art oder Projekt &amp;öffnen…</translation>
    </message>
    <message>
        <source>Colouring by node attributes needs a single tree: the forest is shown in its materials</source>
        <translation>Das Einfärben nach Knotenattributen braucht einen einzelnen Baum: Der Wald wird in seinen Materialien gezeigt</translation>
    </message>
    <message>
        <source>Open species or project</source>
        <translation>Art oder Projekt öffnen</translation>
    </message>
    <message>
        <source>Species, grammars and projects (*.json *.lsys *.txt *.sylva);;Projects (*.sylva);;All files (*)</source>
        <translation>Arten, Grammatiken und Projekte (*.json *.lsys *.txt *.sylva);;Projekte (*.sylva);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exportieren…</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Nothing to export yet.</source>
        <translation>Noch nichts zu exportieren.</translation>
    </message>
    <message>
        <source>Could not export %1: %2</source>
        <translation>Konnte %1 nicht exportieren: %2</translation>
    </message>
    <message numerus="yes">
        <source>Exported %n tree(s) to %1 (%2 files)</source>
        <translation>
            <numerusform>%n Baum nach %1 exportiert (%2 Dateien)</numerusform>
            <numerusform>%n Bäume nach %1 exportiert (%2 Dateien)</numerusform>
        </translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Wavefront OBJ (*.obj);;glTF binary (*.glb);;glTF (*.gltf);;FBX binary (*.fbx)</source>
        <translation>Wavefront OBJ (*.obj);;glTF binär (*.glb);;glTF (*.gltf);;FBX binär (*.fbx)</translation>
    </message>
    <message>
        <source>Reload &amp;automatically</source>
        <translation>&amp;Automatisch neu laden</translation>
    </message>
</context>
<context>
    <name>sylva::ui::StatsPanel</name>
    <message>
        <source>Species:</source>
        <translation>Art:</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <source>Vertices:</source>
        <translation>Eckpunkte:</translation>
    </message>
    <message>
        <source>Triangles:</source>
        <translation>Dreiecke:</translation>
    </message>
    <message>
        <source>Segments:</source>
        <translation>Segmente:</translation>
    </message>
    <message>
        <source>Leaves:</source>
        <translation>Blätter:</translation>
    </message>
    <message>
        <source>Height:</source>
        <translation>Höhe:</translation>
    </message>
    <message>
        <source>Generation time:</source>
        <translation>Erzeugungszeit:</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Generating %1…</source>
        <translation>Erzeuge %1…</translation>
    </message>
    <message>
        <source>Trees:</source>
        <translation>Bäume:</translation>
    </message>
    <message>
        <source>CO₂ stored:</source>
        <translation>Gespeichertes CO₂:</translation>
    </message>
    <message>
        <source>%1 t</source>
        <translation>%1 t</translation>
    </message>
</context>
<context>
    <name>sylva::ui::Viewport</name>
    <message>
        <source>OpenGL 3.3 core profile is not available (got %1.%2).</source>
        <translation>OpenGL 3.3 Core Profile ist nicht verfügbar (erhalten: %1.%2).</translation>
    </message>
    <message>
        <source>The mesh has an index out of range; it is not drawn.</source>
        <translation>Das Netz hat einen ungültigen Index und wird nicht gezeichnet.</translation>
    </message>
</context>
</TS>
