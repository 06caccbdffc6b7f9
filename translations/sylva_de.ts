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
    <name>Commands</name>
    <message>
        <source>Remove tree</source>
        <translation>Baum entfernen</translation>
    </message>
    <message>
        <source>Remove trees</source>
        <translation>Bäume entfernen</translation>
    </message>
    <message>
        <source>Duplicate tree</source>
        <translation>Baum duplizieren</translation>
    </message>
    <message>
        <source>Duplicate trees</source>
        <translation>Bäume duplizieren</translation>
    </message>
    <message>
        <source>Add species</source>
        <translation>Art hinzufügen</translation>
    </message>
    <message>
        <source>Rename species</source>
        <translation>Art umbenennen</translation>
    </message>
    <message>
        <source>Change variants</source>
        <translation>Varianten ändern</translation>
    </message>
    <message>
        <source>Remove species</source>
        <translation>Art entfernen</translation>
    </message>
    <message>
        <source>Edit grammar</source>
        <translation>Grammatik bearbeiten</translation>
    </message>
    <message>
        <source>Change project seed</source>
        <translation>Startwert des Projekts ändern</translation>
    </message>
    <message>
        <source>Change wind</source>
        <translation>Wind ändern</translation>
    </message>
    <message>
        <source>Move camera</source>
        <translation>Kamera bewegen</translation>
    </message>
    <message>
        <source>Change light</source>
        <translation>Licht ändern</translation>
    </message>
    <message>
        <source>Add tree</source>
        <translation>Baum hinzufügen</translation>
    </message>
    <message>
        <source>Edit tree</source>
        <translation>Baum bearbeiten</translation>
    </message>
    <message>
        <source>Move tree</source>
        <translation>Baum verschieben</translation>
    </message>
    <message>
        <source>Rotate tree</source>
        <translation>Baum drehen</translation>
    </message>
    <message>
        <source>Scale tree</source>
        <translation>Baum skalieren</translation>
    </message>
    <message>
        <source>Change tree seed</source>
        <translation>Startwert des Baums ändern</translation>
    </message>
    <message>
        <source>Change tree species</source>
        <translation>Art des Baums ändern</translation>
    </message>
    <message>
        <source>Change tree growth</source>
        <translation>Wachstum des Baums ändern</translation>
    </message>
    <message>
        <source>Remove obstacle</source>
        <translation>Hindernis entfernen</translation>
    </message>
    <message>
        <source>Add obstacle</source>
        <translation>Hindernis hinzufügen</translation>
    </message>
    <message>
        <source>Remove domain</source>
        <translation>Bereich entfernen</translation>
    </message>
    <message>
        <source>Add domain</source>
        <translation>Bereich hinzufügen</translation>
    </message>
    <message>
        <source>Transform obstacle</source>
        <translation>Hindernis transformieren</translation>
    </message>
    <message>
        <source>Change obstacle mesh</source>
        <translation>Netz des Hindernisses ändern</translation>
    </message>
    <message>
        <source>Change tree counts</source>
        <translation>Baumanzahlen ändern</translation>
    </message>
    <message>
        <source>Change domain</source>
        <translation>Bereich ändern</translation>
    </message>
    <message>
        <source>Add node %1</source>
        <translation>Knoten %1 hinzufügen</translation>
    </message>
    <message>
        <source>Delete node %1</source>
        <translation>Knoten %1 löschen</translation>
    </message>
    <message>
        <source>Connect %1 to %2</source>
        <translation>%1 mit %2 verbinden</translation>
    </message>
    <message>
        <source>Disconnect %1 from %2</source>
        <translation>%1 von %2 trennen</translation>
    </message>
    <message>
        <source>Make %1 the output</source>
        <translation>%1 zur Ausgabe machen</translation>
    </message>
    <message>
        <source>Move node %1</source>
        <translation>Knoten %1 verschieben</translation>
    </message>
    <message>
        <source>Apply preset %1</source>
        <translation>Vorlage %1 anwenden</translation>
    </message>
    <message>
        <source>Delete connection</source>
        <translation>Verbindung löschen</translation>
    </message>
    <message>
        <source>Delete nodes</source>
        <translation>Knoten löschen</translation>
    </message>
    <message>
        <source>Paste nodes</source>
        <translation>Knoten einfügen</translation>
    </message>
    <message>
        <source>Move nodes</source>
        <translation>Knoten verschieben</translation>
    </message>
    <message>
        <source>Change season</source>
        <translation>Jahreszeit ändern</translation>
    </message>
    <message>
        <source>Change tree season</source>
        <translation>Jahreszeit des Baums ändern</translation>
    </message>
    <message>
        <source>Edit branch</source>
        <translation>Ast bearbeiten</translation>
    </message>
    <message>
        <source>Prune branch</source>
        <translation>Ast entfernen</translation>
    </message>
    <message>
        <source>Clear branch edits</source>
        <translation>Astbearbeitungen löschen</translation>
    </message>
    <message>
        <source>Change %1 (%2)</source>
        <translation>%1 ändern (%2)</translation>
    </message>
</context>
<context>
    <name>Document</name>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
</context>
<context>
    <name>NodeGraph</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>tree ▶</source>
        <translation>Baum ▶</translation>
    </message>
    <message>
        <source>✖ %1</source>
        <translation>✖ %1</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1 ms (cached)</source>
        <translation>%1 ms (zwischengespeichert)</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>%1: the species&apos; output node produced no mesh</source>
        <translation>%1: Der Ausgabeknoten der Art hat kein Netz erzeugt</translation>
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
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>TextureImage</name>
    <message>
        <source>Texture %1 cannot be read (%2); drawn without it</source>
        <translation>Textur %1 kann nicht gelesen werden (%2); ohne sie gezeichnet</translation>
    </message>
    <message>
        <source>Texture %1 is %2 × %3 pixels, more than the %4 pixels (16384 × 16384) the editor decodes; drawn without it (exports copy it unchanged). Use a smaller texture.</source>
        <translation>Textur %1 hat %2 × %3 Pixel, mehr als die %4 Pixel (16384 × 16384), die der Editor dekodiert; ohne sie gezeichnet (Exporte kopieren sie unverändert). Verwenden Sie eine kleinere Textur.</translation>
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
    <message>
        <source>Run the Python script &lt;file&gt; in the editor (after opening the project, if one is given) and exit with its status.</source>
        <translation>Das Python-Skript &lt;file&gt; im Editor ausführen (nach dem Öffnen des Projekts, falls eines angegeben ist) und mit dessen Exit-Status beenden.</translation>
    </message>
    <message>
        <source>Restore edits autosaved before a crash without asking.</source>
        <translation>Vor einem Absturz automatisch gespeicherte Änderungen ohne Rückfrage wiederherstellen.</translation>
    </message>
    <message>
        <source>Discard edits autosaved before a crash without asking.</source>
        <translation>Vor einem Absturz automatisch gespeicherte Änderungen ohne Rückfrage verwerfen.</translation>
    </message>
</context>
<context>
    <name>sylva::doc::ProjectSettings</name>
    <message>
        <source>Wind direction</source>
        <translation>Windrichtung</translation>
    </message>
    <message>
        <source>Where the wind blows to, about the vertical: 0° along +X, 90° along +Z</source>
        <translation>Wohin der Wind weht, um die Senkrechte: 0° entlang +X, 90° entlang +Z</translation>
    </message>
    <message>
        <source>Wind strength</source>
        <translation>Windstärke</translation>
    </message>
    <message>
        <source>0 calm, 1 strong, 2 storm: trees bend with its square</source>
        <translation>0 windstill, 1 stark, 2 Sturm: Bäume biegen sich mit ihrem Quadrat</translation>
    </message>
    <message>
        <source>Gustiness</source>
        <translation>Böigkeit</translation>
    </message>
    <message>
        <source>0 a steady wind, 1 gusts that double the pressure</source>
        <translation>0 gleichmäßiger Wind, 1 Böen, die den Druck verdoppeln</translation>
    </message>
    <message>
        <source>Sway frequency</source>
        <translation>Schwingfrequenz</translation>
    </message>
    <message>
        <source>How often the trunks sway; limbs, branches and leaves go faster</source>
        <translation>Wie oft die Stämme schwingen; Äste, Zweige und Blätter schneller</translation>
    </message>
    <message>
        <source>Variants</source>
        <translation>Varianten</translation>
    </message>
    <message>
        <source>How many different trees of this species the forest is made of: a tree that touches no obstacle and no neighbour&apos;s crown shows one of them, turned and scaled; one that does is cut back from one of them. Fewer variants generate and export faster; 0 grows every tree for its place.</source>
        <translation>Wie viele verschiedene Bäume dieser Art den Wald bilden: ein Baum, der kein Hindernis und keine Nachbarkrone berührt, zeigt einen davon, gedreht und skaliert; einer, der es tut, wird aus einem davon zurückgeschnitten. Weniger Varianten erzeugen und exportieren schneller; 0 lässt jeden Baum für seinen Platz wachsen.</translation>
    </message>
</context>
<context>
    <name>sylva::ui::BranchProperties</name>
    <message>
        <source>Branch %1</source>
        <translation>Ast %1</translation>
    </message>
    <message>
        <source>Edit:</source>
        <translation>Bearbeitung:</translation>
    </message>
    <message>
        <source>Length scale:</source>
        <translation>Längenfaktor:</translation>
    </message>
    <message>
        <source>Scales the branch&apos;s own length about its base, 0.05 to 20; what it carries follows</source>
        <translation>Skaliert die eigene Länge des Asts um seine Basis, 0,05 bis 20; was er trägt, folgt</translation>
    </message>
    <message>
        <source>Radius scale:</source>
        <translation>Radiusfaktor:</translation>
    </message>
    <message>
        <source>Scales the thickness of the branch and what it carries, 0.05 to 20</source>
        <translation>Skaliert die Dicke des Asts und dessen, was er trägt, 0,05 bis 20</translation>
    </message>
    <message>
        <source>Locked: the branch and what it carries keep their exact shape when the species or the seed changes</source>
        <translation>Gesperrt: Der Ast und was er trägt behalten ihre genaue Form, wenn sich die Art oder der Seed ändert</translation>
    </message>
    <message>
        <source>Lock:</source>
        <translation>Sperren:</translation>
    </message>
    <message>
        <source>Prune</source>
        <translation>Schneiden</translation>
    </message>
    <message>
        <source>Removes the branch and everything it carries (Delete)</source>
        <translation>Entfernt den Ast und alles, was er trägt (Entf)</translation>
    </message>
    <message>
        <source>pruned</source>
        <translation>geschnitten</translation>
    </message>
    <message>
        <source>bent</source>
        <translation>gebogen</translation>
    </message>
    <message>
        <source>length ×%1</source>
        <translation>Länge ×%1</translation>
    </message>
    <message>
        <source>radius ×%1</source>
        <translation>Radius ×%1</translation>
    </message>
    <message>
        <source>locked</source>
        <translation>gesperrt</translation>
    </message>
    <message>
        <source>none (as grown)</source>
        <translation>keine (wie gewachsen)</translation>
    </message>
    <message>
        <source>Keep through regrowth</source>
        <translation>Beim Neuwachsen behalten</translation>
    </message>
</context>
<context>
    <name>sylva::ui::ColorByMenu</name>
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
</context>
<context>
    <name>sylva::ui::CurveEditor</name>
    <message>
        <source>Drag a point to shape the curve; double-click to add a point; right-click or Delete removes one</source>
        <translation>Einen Punkt ziehen formt die Kurve; Doppelklick fügt einen Punkt hinzu; Rechtsklick oder Entf entfernt einen</translation>
    </message>
</context>
<context>
    <name>sylva::ui::DocumentActions</name>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>&amp;Duplizieren</translation>
    </message>
    <message>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <source>Select &amp;all trees</source>
        <translation>&amp;Alle Bäume auswählen</translation>
    </message>
    <message>
        <source>Add &amp;species from file…</source>
        <translation>&amp;Art aus Datei hinzufügen…</translation>
    </message>
    <message>
        <source>Add &amp;tree</source>
        <translation>&amp;Baum hinzufügen</translation>
    </message>
    <message>
        <source>Ctrl+T</source>
        <translation>Ctrl+T</translation>
    </message>
    <message>
        <source>Import &amp;obstacle…</source>
        <translation>&amp;Hindernis importieren…</translation>
    </message>
    <message>
        <source>Add &amp;domain</source>
        <translation>Be&amp;reich hinzufügen</translation>
    </message>
    <message>
        <source>Add species</source>
        <translation>Art hinzufügen</translation>
    </message>
    <message>
        <source>Species and grammars (*.json *.lsys *.txt);;All files (*)</source>
        <translation>Arten und Grammatiken (*.json *.lsys *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Name in the project:</source>
        <translation>Name im Projekt:</translation>
    </message>
    <message>
        <source>Import obstacle</source>
        <translation>Hindernis importieren</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.ply *.stl *.fbx *.gltf *.glb *.dae *.3ds *.off);;All files (*)</source>
        <translation>Netze (*.obj *.ply *.stl *.fbx *.gltf *.glb *.dae *.3ds *.off);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>sylva::ui::DocumentGenerator</name>
    <message>
        <source>the generation failed</source>
        <translation>die Erzeugung ist fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>sylva::ui::FileDialogs</name>
    <message>
        <source>Open species or project</source>
        <translation>Art oder Projekt öffnen</translation>
    </message>
    <message>
        <source>Species, grammars and projects (*.json *.lsys *.txt *.sylva);;Projects (*.sylva);;All files (*)</source>
        <translation>Arten, Grammatiken und Projekte (*.json *.lsys *.txt *.sylva);;Projekte (*.sylva);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save project as</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <source>Sylva projects (*.sylva)</source>
        <translation>Sylva-Projekte (*.sylva)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>Bildschirmfoto speichern</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.bmp)</source>
        <translation>Bilder (*.png *.jpg *.bmp)</translation>
    </message>
</context>
<context>
    <name>sylva::ui::GrammarEditor</name>
    <message>
        <source>Step through the derivation: the preview shows the tree after this many generations (the grammar keeps its own count)</source>
        <translation>Schrittweise durch die Ableitung: die Vorschau zeigt den Baum nach so vielen Generationen (die Grammatik behält ihre eigene Anzahl)</translation>
    </message>
    <message>
        <source>Animate</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Play the derivation from the axiom to the last generation</source>
        <translation>Die Ableitung vom Axiom bis zur letzten Generation abspielen</translation>
    </message>
    <message>
        <source>Symbols</source>
        <translation>Symbole</translation>
    </message>
    <message>
        <source>Generations:</source>
        <translation>Generationen:</translation>
    </message>
    <message>
        <source>&lt;table cellspacing=4&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; f&lt;/td&gt;&lt;td&gt;move forward drawing / without drawing (length, m)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;+ -&lt;/b&gt;&lt;/td&gt;&lt;td&gt;turn left / right (angle, °)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;&amp;amp; ^&lt;/b&gt;&lt;/td&gt;&lt;td&gt;pitch down / up (°)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;\ /&lt;/b&gt;&lt;/td&gt;&lt;td&gt;roll left / right (°)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;|&lt;/b&gt;&lt;/td&gt;&lt;td&gt;turn around&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;[ ]&lt;/b&gt;&lt;/td&gt;&lt;td&gt;start / end a branch&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;!&lt;/b&gt;&lt;/td&gt;&lt;td&gt;width: set (diameter, m) or multiply by width_factor&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;$&lt;/b&gt; &lt;b&gt;%&lt;/b&gt;&lt;/td&gt;&lt;td&gt;roll left horizontal / cut the branch&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;J&lt;/b&gt;&lt;/td&gt;&lt;td&gt;a leaf (size, m)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;A B X …&lt;/td&gt;&lt;td&gt;other modules: state for the rules&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;a &amp;lt; B &amp;gt; c&lt;/td&gt;&lt;td&gt;context; &lt;b&gt;: cond&lt;/b&gt; before -&amp;gt;, &lt;b&gt;: weight&lt;/b&gt; after the successor&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table cellspacing=4&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; f&lt;/td&gt;&lt;td&gt;vorwärts mit / ohne Zeichnen (Länge, m)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;+ -&lt;/b&gt;&lt;/td&gt;&lt;td&gt;links / rechts drehen (Winkel, °)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;&amp;amp; ^&lt;/b&gt;&lt;/td&gt;&lt;td&gt;nach unten / oben neigen (°)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;\ /&lt;/b&gt;&lt;/td&gt;&lt;td&gt;links / rechts rollen (°)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;|&lt;/b&gt;&lt;/td&gt;&lt;td&gt;umkehren&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;[ ]&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Ast beginnen / beenden&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;!&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Breite: setzen (Durchmesser, m) oder mit width_factor multiplizieren&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;$&lt;/b&gt; &lt;b&gt;%&lt;/b&gt;&lt;/td&gt;&lt;td&gt;waagrecht rollen / Ast abschneiden&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;J&lt;/b&gt;&lt;/td&gt;&lt;td&gt;ein Blatt (Größe, m)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;A B X …&lt;/td&gt;&lt;td&gt;andere Module: Zustand für die Regeln&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;a &amp;lt; B &amp;gt; c&lt;/td&gt;&lt;td&gt;Kontext; &lt;b&gt;: Bedingung&lt;/b&gt; vor -&amp;gt;, &lt;b&gt;: Gewicht&lt;/b&gt; nach dem Nachfolger&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Errors in the grammar: click one to jump to it</source>
        <translation>Fehler in der Grammatik: anklicken, um dorthin zu springen</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>Select an lsystem node to edit its grammar.</source>
        <translation>Einen lsystem-Knoten wählen, um seine Grammatik zu bearbeiten.</translation>
    </message>
    <message>
        <source>Grammar of %1 · %2 (kept in the project)</source>
        <translation>Grammatik von %1 · %2 (im Projekt gespeichert)</translation>
    </message>
    <message>
        <source>Grammar of %1 · %2, read from %3; your edits are kept in the project, the file is not written</source>
        <translation>Grammatik von %1 · %2, gelesen aus %3; Ihre Änderungen werden im Projekt gespeichert, die Datei wird nicht geschrieben</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <translation>Zeile %1, Spalte %2: %3</translation>
    </message>
    <message>
        <source>No errors</source>
        <translation>Keine Fehler</translation>
    </message>
    <message>
        <source>The rule that grew the branch you clicked in the preview</source>
        <translation>Die Regel, die den in der Vorschau angeklickten Ast erzeugt hat</translation>
    </message>
</context>
<context>
    <name>sylva::ui::HelpMenu</name>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;Documentation</source>
        <translation>&amp;Dokumentation</translation>
    </message>
    <message>
        <source>&amp;About Sylva</source>
        <translation>&amp;Über Sylva</translation>
    </message>
    <message>
        <source>About Sylva</source>
        <translation>Über Sylva</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Sylva %1&lt;/h3&gt;&lt;p&gt;Procedural trees and forests for film and games: L-systems, space colonization and self-organizing trees, forests that react to the scene they stand in.&lt;/p&gt;&lt;p&gt;Scripting: Python (the Python Console, or &lt;tt&gt;sylva --script file.py&lt;/tt&gt;).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Sylva %1&lt;/h3&gt;&lt;p&gt;Prozedurale Bäume und Wälder für Film und Spiele: L-Systeme, Space Colonization und selbstorganisierende Bäume, Wälder, die auf die Szene reagieren, in der sie stehen.&lt;/p&gt;&lt;p&gt;Skripting: Python (die Python-Konsole oder &lt;tt&gt;sylva --script file.py&lt;/tt&gt;).&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>sylva::ui::LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Systemstandard</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>Sylva will use the new language when it starts again.</source>
        <translation>Sylva verwendet die neue Sprache beim nächsten Start.</translation>
    </message>
</context>
<context>
    <name>sylva::ui::LodChainExportAction</name>
    <message>
        <source>Export &amp;LOD chain…</source>
        <translation>&amp;LOD-Kette exportieren…</translation>
    </message>
    <message>
        <source>Writes the species&apos; or the selected tree&apos;s game LOD chain (LOD0 to LOD3 and the impostor as glTF, FBX, USD, OBJ and PNG maps) into a folder, as sylva-cli lods does</source>
        <translation>Schreibt die Spiel-LOD-Kette der Art oder des ausgewählten Baums (LOD0 bis LOD3 und den Impostor als glTF, FBX, USD, OBJ und PNG-Karten) in einen Ordner, wie sylva-cli lods</translation>
    </message>
    <message>
        <source>Export LOD chain into folder</source>
        <translation>LOD-Kette in Ordner exportieren</translation>
    </message>
    <message>
        <source>Select one tree, or open a species, to export its LOD chain.</source>
        <translation>Wählen Sie einen Baum aus oder öffnen Sie eine Art, um deren LOD-Kette zu exportieren.</translation>
    </message>
    <message>
        <source>Exporting the LOD chain of %1…</source>
        <translation>LOD-Kette von %1 wird exportiert…</translation>
    </message>
    <message>
        <source>Export LOD chain</source>
        <translation>LOD-Kette exportieren</translation>
    </message>
    <message>
        <source>LOD chain export cancelled: nothing was written.</source>
        <translation>Export der LOD-Kette abgebrochen: nichts wurde geschrieben.</translation>
    </message>
    <message>
        <source>Exported the LOD chain of %1 (%2 levels and the impostor) to %3</source>
        <translation>LOD-Kette von %1 (%2 Stufen und der Impostor) nach %3 exportiert</translation>
    </message>
    <message numerus="yes">
        <source>; %n budget(s) left out: the tree has too few triangles for them</source>
        <translation>
            <numerusform>; %n Budget ausgelassen: der Baum hat zu wenige Dreiecke dafür</numerusform>
            <numerusform>; %n Budgets ausgelassen: der Baum hat zu wenige Dreiecke dafür</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sylva::ui::MainWindow</name>
    <message>
        <source>Sylva</source>
        <translation>Sylva</translation>
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
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Show &amp;grid</source>
        <translation>&amp;Gitter anzeigen</translation>
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
        <source>&amp;Open species or project…</source>
        <translation>Art oder Projekt &amp;öffnen…</translation>
    </message>
    <message>
        <source>Colouring by node attributes needs a single tree: the forest is shown in its materials</source>
        <translation>Das Einfärben nach Knotenattributen braucht einen einzelnen Baum: Der Wald wird in seinen Materialien gezeigt</translation>
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
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>Nothing to export yet.</source>
        <translation>Noch nichts zu exportieren.</translation>
    </message>
    <message>
        <source>Export with the project&apos;s wind</source>
        <translation>Mit dem Wind des Projekts exportieren</translation>
    </message>
    <message>
        <source>When the project has a wind, File ▸ Export writes it as sylva-cli forest --wind: a rig and a looping wind clip per tree (.glb, .gltf, .fbx)</source>
        <translation>Hat das Projekt einen Wind, schreibt Datei ▸ Exportieren ihn wie sylva-cli forest --wind: ein Rig und einen sich wiederholenden Wind-Clip pro Baum (.glb, .gltf, .fbx)</translation>
    </message>
    <message numerus="yes">
        <source>Exported %n tree(s) with the project&apos;s wind to %1 (%2 files)</source>
        <translation>
            <numerusform>%n Baum mit dem Wind des Projekts nach %1 exportiert (%2 Dateien)</numerusform>
            <numerusform>%n Bäume mit dem Wind des Projekts nach %1 exportiert (%2 Dateien)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Exported %n tree(s) to %1 (%2 files)</source>
        <translation>
            <numerusform>%n Baum nach %1 exportiert (%2 Dateien)</numerusform>
            <numerusform>%n Bäume nach %1 exportiert (%2 Dateien)</numerusform>
        </translation>
    </message>
    <message>
        <source>Reload &amp;automatically</source>
        <translation>&amp;Automatisch neu laden</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop the generation; the last result stays</source>
        <translation>Erzeugung anhalten; das letzte Ergebnis bleibt erhalten</translation>
    </message>
    <message>
        <source>Regrowing: %1</source>
        <translation>Wachstum wird neu berechnet: %1</translation>
    </message>
    <message>
        <source>Generation cancelled; the last result stays</source>
        <translation>Erzeugung abgebrochen; das letzte Ergebnis bleibt erhalten</translation>
    </message>
    <message>
        <source>Updated in %1 ms (edit to screen, %2 tree(s) regrown)</source>
        <translation>In %1 ms aktualisiert (von der Bearbeitung bis zur Anzeige; neu gewachsene Bäume: %2)</translation>
    </message>
    <message>
        <source>Autosaved to %1</source>
        <translation>Automatisch in %1 gespeichert</translation>
    </message>
    <message>
        <source>Outliner</source>
        <translation>Gliederung</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Statistics</source>
        <translation>Statistik</translation>
    </message>
    <message>
        <source>&lt;opened&gt;</source>
        <translation>&lt;geöffnet&gt;</translation>
    </message>
    <message>
        <source>Undo History</source>
        <translation>Bearbeitungsverlauf</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Meldungen</translation>
    </message>
    <message>
        <source>Python Console</source>
        <translation>Python-Konsole</translation>
    </message>
    <message>
        <source>&amp;New project</source>
        <translation>Neues &amp;Projekt</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;as…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>Zu&amp;rücksetzen</translation>
    </message>
    <message>
        <source>Save s&amp;creenshot…</source>
        <translation>Bildschirm&amp;foto speichern…</translation>
    </message>
    <message>
        <source>Ctrl+Alt+S</source>
        <translation>Ctrl+Alt+S</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
    <message>
        <source>Ctrl+Y</source>
        <translation>Ctrl+Y</translation>
    </message>
    <message>
        <source>&amp;Scene</source>
        <translation>&amp;Szene</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Bedienfelder</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Revert to the saved file and lose your edits?</source>
        <translation>Zur gespeicherten Datei zurückkehren und Ihre Änderungen verwerfen?</translation>
    </message>
    <message>
        <source>%1 (preview) — Sylva</source>
        <translation>%1 (Vorschau) — Sylva</translation>
    </message>
    <message numerus="yes">
        <source>%1 (%n trees)</source>
        <translation>
            <numerusform>%1 (%n Baum)</numerusform>
            <numerusform>%1 (%n Bäume)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1[*] — Sylva</source>
        <translation>%1[*] — Sylva</translation>
    </message>
    <message>
        <source>%1 has unsaved edits. Save them first?</source>
        <translation>%1 hat ungespeicherte Änderungen. Zuerst speichern?</translation>
    </message>
    <message>
        <source>an untitled project</source>
        <translation>einem unbenannten Projekt</translation>
    </message>
    <message>
        <source>Sylva found edits of %1 autosaved at %2 that were never saved (the editor did not close normally). Restore them?</source>
        <translation>Sylva hat am %2 automatisch gesicherte Änderungen an %1 gefunden, die nie gespeichert wurden (der Editor wurde nicht normal beendet). Wiederherstellen?</translation>
    </message>
    <message>
        <source>Restored the autosaved edits of %1</source>
        <translation>Automatisch gesicherte Änderungen an %1 wiederhergestellt</translation>
    </message>
    <message>
        <source>%1 changed on disk. Reload it and lose your unsaved edits?</source>
        <translation>%1 wurde auf der Festplatte geändert. Neu laden und ungespeicherte Änderungen verwerfen?</translation>
    </message>
    <message>
        <source>Export only the selection</source>
        <translation>Nur die Auswahl exportieren</translation>
    </message>
    <message>
        <source>File ▸ Export writes only the selected trees</source>
        <translation>Datei ▸ Exportieren schreibt nur die ausgewählten Bäume</translation>
    </message>
    <message>
        <source>Export with the viewport camera&apos;s detail</source>
        <translation>Mit dem Detailgrad der Ansichtskamera exportieren</translation>
    </message>
    <message>
        <source>File ▸ Export chooses each tree&apos;s level of detail for the viewport&apos;s camera instead of the project&apos;s camera</source>
        <translation>Datei ▸ Exportieren wählt den Detailgrad jedes Baums für die Kamera der Ansicht statt für die Kamera des Projekts</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>&amp;Frame selection or all</source>
        <translation>&amp;Auswahl oder alles einpassen</translation>
    </message>
    <message>
        <source>Species Editor</source>
        <translation>Arteditor</translation>
    </message>
    <message>
        <source>Node Parameters</source>
        <translation>Knotenparameter</translation>
    </message>
    <message>
        <source>The project has no species to edit: add one from the Presets menu</source>
        <translation>Das Projekt hat keine Art zum Bearbeiten: fügen Sie eine aus dem Menü Vorlagen hinzu</translation>
    </message>
    <message>
        <source>&amp;Edit species…</source>
        <translation>Art &amp;bearbeiten…</translation>
    </message>
    <message>
        <source>Preset Browser</source>
        <translation>Vorlagenbrowser</translation>
    </message>
    <message>
        <source>&amp;Wind</source>
        <translation>&amp;Wind</translation>
    </message>
    <message>
        <source>Trees sway in the project&apos;s wind (Properties, with nothing selected): the wind model the exports carry</source>
        <translation>Bäume wiegen sich im Wind des Projekts (Eigenschaften, wenn nichts ausgewählt ist): das Windmodell, das auch die Exporte tragen</translation>
    </message>
    <message>
        <source>Species preview (%1): %2</source>
        <translation>Artvorschau (%1): %2</translation>
    </message>
    <message>
        <source>Generation failed: %1</source>
        <translation>Erzeugung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Exporting to %1…</source>
        <translation>Exportiere nach %1…</translation>
    </message>
    <message>
        <source>Export cancelled: nothing was written.</source>
        <translation>Export abgebrochen: nichts wurde geschrieben.</translation>
    </message>
</context>
<context>
    <name>sylva::ui::MessagesPanel</name>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
</context>
<context>
    <name>sylva::ui::NodeGraphScene</name>
    <message>
        <source>Added %1</source>
        <translation>%1 hinzugefügt</translation>
    </message>
    <message>
        <source>Connected %1 to %2</source>
        <translation>%1 mit %2 verbunden</translation>
    </message>
    <message>
        <source>Disconnected %1 from %2</source>
        <translation>%1 von %2 getrennt</translation>
    </message>
    <message>
        <source>Deleted %1</source>
        <translation>%1 gelöscht</translation>
    </message>
    <message>
        <source>a connection</source>
        <translation>eine Verbindung</translation>
    </message>
    <message>
        <source>Pasted %1</source>
        <translation>%1 eingefügt</translation>
    </message>
</context>
<context>
    <name>sylva::ui::NodeGraphView</name>
    <message>
        <source>Species graph: drag from a node&apos;s right port to another node to connect; Tab or right click adds a node; Delete removes; Ctrl+C/Ctrl+V copy and paste; F frames all</source>
        <translation>Artgraph: vom rechten Anschluss eines Knotens auf einen anderen ziehen, um zu verbinden; Tab oder Rechtsklick fügt einen Knoten hinzu; Entf löscht; Strg+C/Strg+V kopieren und einfügen; F zeigt alles</translation>
    </message>
    <message>
        <source>Search node types…</source>
        <translation>Knotentypen suchen…</translation>
    </message>
    <message>
        <source>%1  —  %2</source>
        <translation>%1  —  %2</translation>
    </message>
    <message>
        <source>Make it the tree (output)</source>
        <translation>Zum Baum machen (Ausgabe)</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
</context>
<context>
    <name>sylva::ui::OutlinerModel</name>
    <message>
        <source>cannot read: %1</source>
        <translation>nicht lesbar: %1</translation>
    </message>
    <message>
        <source>Species (%1)</source>
        <translation>Arten (%1)</translation>
    </message>
    <message>
        <source>Trees (%1)</source>
        <translation>Bäume (%1)</translation>
    </message>
    <message>
        <source>Domains (%1)</source>
        <translation>Bereiche (%1)</translation>
    </message>
    <message>
        <source>Obstacles (%1)</source>
        <translation>Hindernisse (%1)</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>Position %1, looking at %2: the LOD reference and the start view</source>
        <translation>Position %1, Blick auf %2: Bezugspunkt für den LOD und Startansicht</translation>
    </message>
    <message>
        <source>Light direction %1</source>
        <translation>Lichtrichtung %1</translation>
    </message>
    <message>
        <source>Stored in the project (edited here)</source>
        <translation>Im Projekt gespeichert (hier bearbeitet)</translation>
    </message>
    <message>
        <source>From %1</source>
        <translation>Aus %1</translation>
    </message>
    <message>
        <source>%1 #%2</source>
        <translation>%1 #%2</translation>
    </message>
    <message>
        <source>At %1 m, rotated %2°, scale %3, seed %4</source>
        <translation>Bei %1 m, um %2° gedreht, Skalierung %3, Startwert %4</translation>
    </message>
    <message>
        <source>%1 %2: %3 trees</source>
        <translation>%1 %2: %3 Bäume</translation>
    </message>
    <message>
        <source>pruned</source>
        <translation>geschnitten</translation>
    </message>
    <message>
        <source>bent</source>
        <translation>gebogen</translation>
    </message>
    <message>
        <source>length ×%1</source>
        <translation>Länge ×%1</translation>
    </message>
    <message>
        <source>radius ×%1</source>
        <translation>Radius ×%1</translation>
    </message>
    <message>
        <source>locked</source>
        <translation>gesperrt</translation>
    </message>
    <message>
        <source>Branch %1: %2</source>
        <translation>Ast %1: %2</translation>
    </message>
    <message>
        <source>%1 (orphaned)</source>
        <translation>%1 (verwaist)</translation>
    </message>
    <message>
        <source>The grown tree has no branch %1 now: the edit is kept and applies again when the branch grows back</source>
        <translation>Der gewachsene Baum hat jetzt keinen Ast %1: Die Bearbeitung bleibt erhalten und gilt wieder, sobald der Ast nachwächst</translation>
    </message>
    <message>
        <source>A hand edit of branch %1 (Branch tool, doc.edit_branch)</source>
        <translation>Eine Handbearbeitung von Ast %1 (Ast-Werkzeug, doc.edit_branch)</translation>
    </message>
</context>
<context>
    <name>sylva::ui::ParameterPanel</name>
    <message>
        <source>&lt;i&gt;Select a node in the species graph to edit its parameters.&lt;/i&gt;</source>
        <translation>&lt;i&gt;Einen Knoten im Artgraph wählen, um seine Parameter zu bearbeiten.&lt;/i&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; — %2&lt;br&gt;&lt;small&gt;%3&lt;/small&gt;</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; — %2&lt;br&gt;&lt;small&gt;%3&lt;/small&gt;</translation>
    </message>
    <message>
        <source>%1
%2 · default %3%4</source>
        <translation>%1
%2 · Standard %3%4</translation>
    </message>
    <message>
        <source>unset</source>
        <translation>nicht gesetzt</translation>
    </message>
    <message>
        <source> · range %1</source>
        <translation> · Bereich %1</translation>
    </message>
    <message>
        <source>Reset %1 to its default (%2)</source>
        <translation>%1 auf den Standard zurücksetzen (%2)</translation>
    </message>
    <message>
        <source>relative to the project</source>
        <translation>relativ zum Projekt</translation>
    </message>
    <message>
        <source>Choose a file</source>
        <translation>Datei wählen</translation>
    </message>
    <message>
        <source>Edit in the grammar editor</source>
        <translation>Im Grammatikeditor bearbeiten</translation>
    </message>
    <message numerus="yes">
        <source>Edit in the grammar editor (%n lines)</source>
        <translation>
            <numerusform>Im Grammatikeditor bearbeiten (%n Zeile)</numerusform>
            <numerusform>Im Grammatikeditor bearbeiten (%n Zeilen)</numerusform>
        </translation>
    </message>
    <message>
        <source>unset (JSON)</source>
        <translation>nicht gesetzt (JSON)</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>height, base → top</source>
        <translation>Höhe, Basis → Spitze</translation>
    </message>
    <message>
        <source>radius (× the envelope radius)</source>
        <translation>Radius (× Hüllradius)</translation>
    </message>
    <message>
        <source>Crown profile:</source>
        <translation>Kronenprofil:</translation>
    </message>
    <message>
        <source>Make the envelope a profile (a solid of revolution you can draw), starting from one of Weber and Penn&apos;s crown shapes</source>
        <translation>Die Hülle zu einem Profil machen (einem zeichenbaren Rotationskörper), ausgehend von einer der Kronenformen von Weber und Penn</translation>
    </message>
    <message>
        <source>start from a shape…</source>
        <translation>von einer Form ausgehen…</translation>
    </message>
    <message>
        <source>conical</source>
        <translation>kegelförmig</translation>
    </message>
    <message>
        <source>spherical</source>
        <translation>kugelförmig</translation>
    </message>
    <message>
        <source>hemispherical</source>
        <translation>halbkugelförmig</translation>
    </message>
    <message>
        <source>cylindrical</source>
        <translation>zylindrisch</translation>
    </message>
    <message>
        <source>tapered cylindrical</source>
        <translation>verjüngt zylindrisch</translation>
    </message>
    <message>
        <source>flame</source>
        <translation>flammenförmig</translation>
    </message>
    <message>
        <source>inverse conical</source>
        <translation>umgekehrt kegelförmig</translation>
    </message>
    <message>
        <source>tend flame</source>
        <translation>zur Flamme neigend</translation>
    </message>
    <message>
        <source>t</source>
        <translation>t</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Drag points; double-click adds one; right-click removes one.</source>
        <translation>Punkte ziehen; Doppelklick fügt einen hinzu; Rechtsklick entfernt einen.</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>While there are unsaved edits, a recovery copy is written this often and a few seconds after the last edit. It never replaces your file.</source>
        <translation>Solange ungespeicherte Änderungen vorliegen, wird in diesem Abstand und einige Sekunden nach der letzten Änderung eine Wiederherstellungskopie geschrieben. Sie ersetzt niemals Ihre Datei.</translation>
    </message>
    <message>
        <source>Autosave every:</source>
        <translation>Automatisch speichern alle:</translation>
    </message>
    <message>
        <source>Recovery folder:</source>
        <translation>Wiederherstellungsordner:</translation>
    </message>
    <message>
        <source>Automatic (off on a software renderer)</source>
        <translation>Automatisch (aus bei Software-Rendering)</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>2× multisampling</source>
        <translation>2× Multisampling</translation>
    </message>
    <message>
        <source>4× multisampling</source>
        <translation>4× Multisampling</translation>
    </message>
    <message>
        <source>8× multisampling</source>
        <translation>8× Multisampling</translation>
    </message>
    <message>
        <source>Smooths the edges in the 3D view. Without a graphics card (a software renderer) it makes every frame two to three times slower. Takes effect when Sylva starts next.</source>
        <translation>Glättet die Kanten in der 3D-Ansicht. Ohne Grafikkarte (Software-Rendering) macht es jedes Bild zwei- bis dreimal langsamer. Wirkt ab dem nächsten Start von Sylva.</translation>
    </message>
    <message>
        <source>Antialiasing:</source>
        <translation>Kantenglättung:</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PresetBrowser</name>
    <message>
        <source>Double-click a preset to apply it to the species</source>
        <translation>Doppelklick auf eine Vorlage wendet sie auf die Art an</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Save species as preset…</source>
        <translation>Art als Vorlage speichern…</translation>
    </message>
    <message>
        <source>Save species as preset</source>
        <translation>Art als Vorlage speichern</translation>
    </message>
    <message>
        <source>Species (*.json)</source>
        <translation>Arten (*.json)</translation>
    </message>
    <message>
        <source>The project has no species to apply a preset to.</source>
        <translation>Das Projekt hat keine Art, auf die eine Vorlage angewendet werden kann.</translation>
    </message>
    <message>
        <source>Apply replaces the graph of species &lt;b&gt;%1&lt;/b&gt; (undoable).</source>
        <translation>Anwenden ersetzt den Graphen der Art &lt;b&gt;%1&lt;/b&gt; (rückgängig machbar).</translation>
    </message>
    <message>
        <source>Applied %1 to %2</source>
        <translation>%1 auf %2 angewendet</translation>
    </message>
    <message>
        <source>Saved %1 as %2</source>
        <translation>%1 als %2 gespeichert</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PresetsMenu</name>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Vorlagen</translation>
    </message>
    <message>
        <source>No presets folder found (set SYLVA_PRESETS_DIR)</source>
        <translation>Kein Vorlagenordner gefunden (SYLVA_PRESETS_DIR setzen)</translation>
    </message>
    <message>
        <source>No presets in %1</source>
        <translation>Keine Vorlagen in %1</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PropertiesPanel</name>
    <message>
        <source>Seed:</source>
        <translation>Startwert:</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <source>The project seed: domain trees take their seeds from it and their ids</source>
        <translation>Der Startwert des Projekts: Die Bäume der Bereiche leiten ihre Startwerte daraus und aus ihren IDs ab</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>noch nicht gespeichert</translation>
    </message>
    <message>
        <source>Tree #%1</source>
        <translation>Baum #%1</translation>
    </message>
    <message>
        <source>Species:</source>
        <translation>Art:</translation>
    </message>
    <message>
        <source>Position:</source>
        <translation>Position:</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Where the trunk meets the ground, metres</source>
        <translation>Punkt, an dem der Stamm den Boden berührt, in Metern</translation>
    </message>
    <message>
        <source>Rotation:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>Turn about the vertical axis, degrees</source>
        <translation>Drehung um die senkrechte Achse, in Grad</translation>
    </message>
    <message>
        <source>Scale:</source>
        <translation>Skalierung:</translation>
    </message>
    <message>
        <source>Uniform size factor, 0.01 to 100</source>
        <translation>Einheitlicher Größenfaktor, 0,01 bis 100</translation>
    </message>
    <message>
        <source>Growth:</source>
        <translation>Wachstum:</translation>
    </message>
    <message>
        <source>Growth stage, 0.01 (sapling) to 1 (mature)</source>
        <translation>Wachstumsstadium, 0,01 (Jungbaum) bis 1 (ausgewachsen)</translation>
    </message>
    <message>
        <source>The tree&apos;s own seed: another seed grows another tree of the species</source>
        <translation>Der eigene Startwert des Baums: Ein anderer Startwert lässt einen anderen Baum derselben Art wachsen</translation>
    </message>
    <message>
        <source>Obstacle %1</source>
        <translation>Hindernis %1</translation>
    </message>
    <message>
        <source>Mesh:</source>
        <translation>Netz:</translation>
    </message>
    <message>
        <source>Translate:</source>
        <translation>Verschiebung:</translation>
    </message>
    <message>
        <source>Moves the mesh, metres</source>
        <translation>Verschiebt das Netz, in Metern</translation>
    </message>
    <message>
        <source>Rotate:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <source>Rotation about x, then y, then z, degrees</source>
        <translation>Drehung um x, dann y, dann z, in Grad</translation>
    </message>
    <message>
        <source>Scale per axis</source>
        <translation>Skalierung pro Achse</translation>
    </message>
    <message>
        <source>Domain %1 (%2)</source>
        <translation>Bereich %1 (%2)</translation>
    </message>
    <message>
        <source>Minimum x, z:</source>
        <translation>Minimum x, z:</translation>
    </message>
    <message>
        <source>Corner of the rectangle on the ground</source>
        <translation>Ecke des Rechtecks auf dem Boden</translation>
    </message>
    <message>
        <source>Maximum x, z:</source>
        <translation>Maximum x, z:</translation>
    </message>
    <message>
        <source>Opposite corner of the rectangle</source>
        <translation>Gegenüberliegende Ecke des Rechtecks</translation>
    </message>
    <message>
        <source>%1 trees:</source>
        <translation>Bäume (%1):</translation>
    </message>
    <message>
        <source>How many trees of this species the domain scatters</source>
        <translation>Anzahl der Bäume dieser Art, die der Bereich verteilt</translation>
    </message>
    <message>
        <source>0 (every tree unique)</source>
        <translation>0 (jeder Baum einzeln)</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Where the camera stands: the reference for level of detail</source>
        <translation>Standort der Kamera: der Bezugspunkt für den Detailgrad</translation>
    </message>
    <message>
        <source>Target:</source>
        <translation>Ziel:</translation>
    </message>
    <message>
        <source>The point the camera looks at</source>
        <translation>Der Punkt, auf den die Kamera blickt</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>Direction:</source>
        <translation>Richtung:</translation>
    </message>
    <message>
        <source>The direction sunlight travels (towards the ground: y &lt; 0); trees grow towards where it comes from</source>
        <translation>Die Richtung, in die das Sonnenlicht fällt (zum Boden hin: y &lt; 0); Bäume wachsen dorthin, woher es kommt</translation>
    </message>
    <message>
        <source>Species</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Stored in the project.</source>
        <translation>Im Projekt gespeichert.</translation>
    </message>
    <message>
        <source>From %1 (stored in the project after its first edit).</source>
        <translation>Aus %1 (nach der ersten Bearbeitung im Projekt gespeichert).</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Frühling</translation>
    </message>
    <message>
        <source>Summer</source>
        <translation>Sommer</translation>
    </message>
    <message>
        <source>Autumn</source>
        <translation>Herbst</translation>
    </message>
    <message>
        <source>Winter</source>
        <translation>Winter</translation>
    </message>
    <message>
        <source>Season:</source>
        <translation>Jahreszeit:</translation>
    </message>
    <message>
        <source>Species&apos; own (summer)</source>
        <translation>Die der Art (Sommer)</translation>
    </message>
    <message>
        <source>The time of year of every tree without a season of its own: deciduous species flush in spring, colour in autumn and are bare in winter; conifers and evergreens stay as they are</source>
        <translation>Die Jahreszeit jedes Baums ohne eigene: Laubbäume treiben im Frühling aus, färben sich im Herbst und sind im Winter kahl; Nadelbäume und Immergrüne bleiben, wie sie sind</translation>
    </message>
    <message>
        <source>Project&apos;s season</source>
        <translation>Jahreszeit des Projekts</translation>
    </message>
    <message>
        <source>This tree&apos;s own time of year, or the project&apos;s season</source>
        <translation>Die eigene Jahreszeit dieses Baums oder die des Projekts</translation>
    </message>
    <message>
        <source>%1 (%2):</source>
        <translation>%1 (%2):</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;%3 hand-placed tree(s). Rename it in the outliner; tune its graph and parameters in the Species Editor (Scene ▸ Edit species…, Ctrl+Shift+E).</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;%3 von Hand gesetzte(r) Baum/Bäume. Im Outliner umbenennen; Graph und Parameter im Arteditor anpassen (Szene ▸ Art bearbeiten…, Strg+Umschalt+E).</translation>
    </message>
    <message>
        <source>:</source>
        <translation>:</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PythonConsole</name>
    <message>
        <source>Python %1: sylva and doc = sylva.document() are ready. Try doc.trees(), doc.species() or doc.add_tree(doc.species()[0], (0, 0, 0)).</source>
        <translation>Python %1: sylva und doc = sylva.document() sind bereit. Probieren Sie doc.trees(), doc.species() oder doc.add_tree(doc.species()[0], (0, 0, 0)).</translation>
    </message>
</context>
<context>
    <name>sylva::ui::RecentFilesMenu</name>
    <message>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>No recent files</source>
        <translation>Keine zuletzt geöffneten Dateien</translation>
    </message>
</context>
<context>
    <name>sylva::ui::SpeciesWorkbench</name>
    <message>
        <source>Species:</source>
        <translation>Art:</translation>
    </message>
    <message>
        <source>Preview: %1 ms from the edit</source>
        <translation>Vorschau: %1 ms nach der Änderung</translation>
    </message>
    <message>
        <source>Species preview: %1 ms from the edit to the new tree on screen</source>
        <translation>Artvorschau: %1 ms von der Änderung bis zum neuen Baum auf dem Bildschirm</translation>
    </message>
    <message>
        <source>Preview failed</source>
        <translation>Vorschau fehlgeschlagen</translation>
    </message>
    <message>
        <source>Evaluation %1 ms</source>
        <translation>Auswertung %1 ms</translation>
    </message>
    <message>
        <source>Click a branch or a leaf to select the node that grew it</source>
        <translation>Einen Ast oder ein Blatt anklicken, um den Knoten zu wählen, der ihn wachsen ließ</translation>
    </message>
    <message>
        <source>A leaf card, grown by node %1</source>
        <translation>Ein Blatt, gewachsen durch Knoten %1</translation>
    </message>
    <message>
        <source>A branch, grown by node %1</source>
        <translation>Ein Ast, gewachsen durch Knoten %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Graph&lt;/b&gt; — how the species grows: Tab adds a node, drag from a right port to a node to connect, Delete removes</source>
        <translation>&lt;b&gt;Graph&lt;/b&gt; — wie die Art wächst: Tab fügt einen Knoten hinzu, vom rechten Anschluss auf einen Knoten ziehen verbindet, Entf löscht</translation>
    </message>
    <message>
        <source>&lt;b&gt;Preview&lt;/b&gt; — one tree; click a branch to select the node that grew it and see its grammar rule</source>
        <translation>&lt;b&gt;Vorschau&lt;/b&gt; — ein Baum; einen Ast anklicken wählt den Knoten, der ihn erzeugt hat, und zeigt seine Grammatikregel</translation>
    </message>
    <message>
        <source>A branch, grown by node %1: the rule on line %2</source>
        <translation>Ein Ast, erzeugt vom Knoten %1: die Regel in Zeile %2</translation>
    </message>
    <message>
        <source>A branch of the clicked tree, grown by node %1: the rule on line %2 (the preview shows that tree, before adaptation)</source>
        <translation>Ein Ast des angeklickten Baums, erzeugt vom Knoten %1: die Regel in Zeile %2 (die Vorschau zeigt diesen Baum vor der Anpassung)</translation>
    </message>
    <message>
        <source>%1, node &apos;%2&apos;</source>
        <translation>%1, Knoten &apos;%2&apos;</translation>
    </message>
    <message>
        <source>Preview failed (%1) — showing the last good tree: %2</source>
        <translation>Vorschau fehlgeschlagen (%1) — der letzte gute Baum wird gezeigt: %2</translation>
    </message>
    <message>
        <source>Preview failed (%1): %2</source>
        <translation>Vorschau fehlgeschlagen (%1): %2</translation>
    </message>
    <message>
        <source>Branch tool: click a branch of the tree to select it, drag it to bend it, Delete prunes it</source>
        <translation>Zweig-Werkzeug: Klicken Sie auf einen Zweig des Baums, um ihn auszuwählen, ziehen Sie ihn, um ihn zu biegen; Entf schneidet ihn ab</translation>
    </message>
</context>
<context>
    <name>sylva::ui::StatsPanel</name>
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
    <message>
        <source>Selection:</source>
        <translation>Auswahl:</translation>
    </message>
    <message>
        <source>nothing selected</source>
        <translation>nichts ausgewählt</translation>
    </message>
    <message numerus="yes">
        <source>%n tree(s)</source>
        <translation>
            <numerusform>%n Baum</numerusform>
            <numerusform>%n Bäume</numerusform>
        </translation>
    </message>
    <message>
        <source>; up to %1 m tall, DBH up to %2 cm; wood %3 m³, biomass %4 kg, CO₂ %5 kg</source>
        <translation>; bis zu %1 m hoch, BHD bis zu %2 cm; Holz %3 m³, Biomasse %4 kg, CO₂ %5 kg</translation>
    </message>
    <message>
        <source>Wood, biomass:</source>
        <translation>Holz, Biomasse:</translation>
    </message>
    <message>
        <source>A project&apos;s wood volume and dry biomass, and the trees&apos; mean DBH</source>
        <translation>Holzvolumen und Trockenbiomasse eines Projekts und der mittlere BHD der Bäume</translation>
    </message>
    <message>
        <source>%1 m³, %2 t; mean DBH %3 cm</source>
        <translation>%1 m³, %2 t; mittlerer BHD %3 cm</translation>
    </message>
    <message>
        <source>Showing:</source>
        <translation>Angezeigt:</translation>
    </message>
    <message>
        <source>The species previewed, or the project and its tree count</source>
        <translation>Die in der Vorschau gezeigte Art, oder das Projekt und seine Baumanzahl</translation>
    </message>
</context>
<context>
    <name>sylva::ui::ToolController</name>
    <message>
        <source>That tree was scattered by domain %1: its counts and extent are in Properties</source>
        <translation>Dieser Baum wurde von Bereich %1 verteilt: Anzahlen und Ausdehnung des Bereichs finden Sie unter Eigenschaften</translation>
    </message>
    <message>
        <source>Move tree</source>
        <translation>Baum verschieben</translation>
    </message>
    <message>
        <source>Move trees</source>
        <translation>Bäume verschieben</translation>
    </message>
    <message>
        <source>Add a species first (Scene ▸ Add species from file…)</source>
        <translation>Fügen Sie zuerst eine Art hinzu (Szene ▸ Art aus Datei hinzufügen…)</translation>
    </message>
    <message>
        <source>A tree cannot stand inside an obstacle&apos;s footprint: the move was refused</source>
        <translation>Ein Baum kann nicht auf der Grundfläche eines Hindernisses stehen: Das Verschieben wurde abgelehnt</translation>
    </message>
    <message numerus="yes">
        <source>Paint %n tree(s)</source>
        <translation>
            <numerusform>%n Baum malen</numerusform>
            <numerusform>%n Bäume malen</numerusform>
        </translation>
    </message>
    <message>
        <source>A tree cannot stand inside an obstacle&apos;s footprint</source>
        <translation>Ein Baum kann nicht auf der Grundfläche eines Hindernisses stehen</translation>
    </message>
    <message>
        <source>A tree&apos;s scale must stay between 0.01 and 100: the change was refused</source>
        <translation>Die Skalierung eines Baums muss zwischen 0,01 und 100 bleiben: die Änderung wurde abgelehnt</translation>
    </message>
    <message>
        <source>Rotate tree</source>
        <translation>Baum drehen</translation>
    </message>
    <message>
        <source>Rotate trees</source>
        <translation>Bäume drehen</translation>
    </message>
    <message>
        <source>Scale tree</source>
        <translation>Baum skalieren</translation>
    </message>
    <message>
        <source>Scale trees</source>
        <translation>Bäume skalieren</translation>
    </message>
    <message>
        <source>No ground under the cursor: nothing planted; click where the ground is drawn</source>
        <translation>Kein Boden unter dem Mauszeiger: nichts gepflanzt; klicken Sie dorthin, wo Boden zu sehen ist</translation>
    </message>
    <message>
        <source>Only hand-placed trees take branch edits: this one was scattered by a domain</source>
        <translation>Nur von Hand gesetzte Bäume nehmen Astbearbeitungen an: Dieser wurde von einer Domäne verteilt</translation>
    </message>
    <message>
        <source>Branch %1 is locked: unlock it in Properties before bending it</source>
        <translation>Ast %1 ist gesperrt: Entsperren Sie ihn in den Eigenschaften, bevor Sie ihn biegen</translation>
    </message>
</context>
<context>
    <name>sylva::ui::ToolOptionsBar</name>
    <message>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <source>Select</source>
        <translation>Auswählen</translation>
    </message>
    <message>
        <source>Click a tree or obstacle to select it (Shift adds, Ctrl toggles, Ctrl+drag draws a box); [ and ] step through the trees</source>
        <translation>Klicken Sie auf einen Baum oder ein Hindernis, um das Objekt auszuwählen (Umschalt fügt hinzu, Strg schaltet die Auswahl um, Strg+Ziehen zieht einen Auswahlrahmen auf); [ und ] springen von Baum zu Baum</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Drag selected trees along the ground (Ctrl+drag rotates, Shift+drag scales; arrow keys nudge). They re-adapt to the obstacles when you let go</source>
        <translation>Ausgewählte Bäume über den Boden ziehen (Strg+Ziehen dreht, Umschalt+Ziehen skaliert; Pfeiltasten verschieben schrittweise). Beim Loslassen passen sie sich erneut an die Hindernisse an</translation>
    </message>
    <message>
        <source>Place</source>
        <translation>Pflanzen</translation>
    </message>
    <message>
        <source>Click the ground to plant a tree of the chosen species</source>
        <translation>Klicken Sie auf den Boden, um einen Baum der gewählten Art zu pflanzen</translation>
    </message>
    <message>
        <source>Brush</source>
        <translation>Pinsel</translation>
    </message>
    <message>
        <source>Paint trees of the species mix with the radius and density below; one stroke is one undo step</source>
        <translation>Bäume der Artenmischung mit dem Radius und der Dichte unten malen; ein Pinselstrich lässt sich in einem Schritt rückgängig machen</translation>
    </message>
    <message>
        <source>Erase</source>
        <translation>Radierer</translation>
    </message>
    <message>
        <source>Remove the hand-placed trees the brush passes over</source>
        <translation>Die von Hand platzierten Bäume entfernen, über die der Pinsel fährt</translation>
    </message>
    <message>
        <source> Species: </source>
        <translation> Art: </translation>
    </message>
    <message>
        <source>The species the Place tool plants, and the Brush when no mix is given</source>
        <translation>Die Art, die das Werkzeug „Pflanzen“ setzt und die der Pinsel malt, wenn keine Mischung angegeben ist</translation>
    </message>
    <message>
        <source> Radius: </source>
        <translation> Radius: </translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Brush and eraser radius, metres</source>
        <translation>Radius von Pinsel und Radierer, in Metern</translation>
    </message>
    <message>
        <source> Density: </source>
        <translation> Dichte: </translation>
    </message>
    <message>
        <source> /100 m²</source>
        <translation> /100 m²</translation>
    </message>
    <message>
        <source>Trees tried per 100 m² under the brush; spacing rules keep trunks out of each other&apos;s crowns and out of obstacles</source>
        <translation>Pflanzversuche pro 100 m² unter dem Pinsel; Abstandsregeln halten die Stämme aus den Kronen der anderen Bäume und aus Hindernissen heraus</translation>
    </message>
    <message>
        <source> Mix: </source>
        <translation> Mischung: </translation>
    </message>
    <message>
        <source>e.g. alder 70, ternary 30</source>
        <translation>z. B. alder 70, ternary 30</translation>
    </message>
    <message>
        <source>Species and weights the brush paints; empty: the chosen species</source>
        <translation>Arten und Gewichte, die der Pinsel malt; leer: die gewählte Art</translation>
    </message>
    <message>
        <source>Branch</source>
        <translation>Ast</translation>
    </message>
    <message>
        <source>Click a branch of a hand-placed tree to select it (its settings in Properties), drag it to bend it about its base, Delete prunes it; each is one undo step</source>
        <translation>Klicken Sie auf einen Ast eines von Hand gesetzten Baums, um ihn auszuwählen (seine Einstellungen in den Eigenschaften), ziehen Sie ihn, um ihn um seine Basis zu biegen, Entf schneidet ihn; jeder Schritt ist ein Rückgängig-Schritt</translation>
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
