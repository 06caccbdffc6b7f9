<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>AttributeColors</name>
    <message>
        <source>Light per internode</source>
        <translation>Lumière par entre-nœud</translation>
    </message>
    <message>
        <source>Vigour (log scale)</source>
        <translation>Vigueur (échelle logarithmique)</translation>
    </message>
    <message>
        <source>Age in cycles</source>
        <translation>Âge en cycles</translation>
    </message>
    <message>
        <source>Branch order</source>
        <translation>Ordre des branches</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Matériaux</translation>
    </message>
    <message>
        <source>%1: not available for this tree</source>
        <translation>%1&#xa0;: non disponible pour cet arbre</translation>
    </message>
    <message>
        <source>%1: 0 (blue) – %2 (yellow)</source>
        <translation>%1&#xa0;: 0 (bleu) – %2 (jaune)</translation>
    </message>
    <message>
        <source>; red: %1 internodes in branches below the shedding threshold %2, shed at the next cycle</source>
        <translation>; rouge&#xa0;: %1 entre-nœuds dans des branches sous le seuil d&apos;élagage %2, élagués au cycle suivant</translation>
    </message>
    <message>
        <source>; no branch is below the shedding threshold %1</source>
        <translation>; aucune branche n&apos;est sous le seuil d&apos;élagage %1</translation>
    </message>
</context>
<context>
    <name>Commands</name>
    <message>
        <source>Remove tree</source>
        <translation>Supprimer l&apos;arbre</translation>
    </message>
    <message>
        <source>Remove trees</source>
        <translation>Supprimer les arbres</translation>
    </message>
    <message>
        <source>Duplicate tree</source>
        <translation>Dupliquer l&apos;arbre</translation>
    </message>
    <message>
        <source>Duplicate trees</source>
        <translation>Dupliquer les arbres</translation>
    </message>
    <message>
        <source>Add species</source>
        <translation>Ajouter une espèce</translation>
    </message>
    <message>
        <source>Rename species</source>
        <translation>Renommer l&apos;espèce</translation>
    </message>
    <message>
        <source>Change variants</source>
        <translation>Modifier les variantes</translation>
    </message>
    <message>
        <source>Remove species</source>
        <translation>Supprimer l&apos;espèce</translation>
    </message>
    <message>
        <source>Edit grammar</source>
        <translation>Modifier la grammaire</translation>
    </message>
    <message>
        <source>Change project seed</source>
        <translation>Modifier la graine du projet</translation>
    </message>
    <message>
        <source>Change wind</source>
        <translation>Modifier le vent</translation>
    </message>
    <message>
        <source>Move camera</source>
        <translation>Déplacer la caméra</translation>
    </message>
    <message>
        <source>Change light</source>
        <translation>Modifier la lumière</translation>
    </message>
    <message>
        <source>Add tree</source>
        <translation>Ajouter un arbre</translation>
    </message>
    <message>
        <source>Edit tree</source>
        <translation>Modifier l&apos;arbre</translation>
    </message>
    <message>
        <source>Move tree</source>
        <translation>Déplacer l&apos;arbre</translation>
    </message>
    <message>
        <source>Rotate tree</source>
        <translation>Faire pivoter l&apos;arbre</translation>
    </message>
    <message>
        <source>Scale tree</source>
        <translation>Mettre l&apos;arbre à l&apos;échelle</translation>
    </message>
    <message>
        <source>Change tree seed</source>
        <translation>Modifier la graine de l&apos;arbre</translation>
    </message>
    <message>
        <source>Change tree species</source>
        <translation>Modifier l&apos;espèce de l&apos;arbre</translation>
    </message>
    <message>
        <source>Change tree growth</source>
        <translation>Modifier la croissance de l&apos;arbre</translation>
    </message>
    <message>
        <source>Remove obstacle</source>
        <translation>Supprimer l&apos;obstacle</translation>
    </message>
    <message>
        <source>Add obstacle</source>
        <translation>Ajouter un obstacle</translation>
    </message>
    <message>
        <source>Remove domain</source>
        <translation>Supprimer la zone</translation>
    </message>
    <message>
        <source>Add domain</source>
        <translation>Ajouter une zone</translation>
    </message>
    <message>
        <source>Transform obstacle</source>
        <translation>Transformer l&apos;obstacle</translation>
    </message>
    <message>
        <source>Change obstacle mesh</source>
        <translation>Modifier le maillage de l&apos;obstacle</translation>
    </message>
    <message>
        <source>Change tree counts</source>
        <translation>Modifier le nombre d&apos;arbres</translation>
    </message>
    <message>
        <source>Change domain</source>
        <translation>Modifier la zone</translation>
    </message>
    <message>
        <source>Add node %1</source>
        <translation>Ajouter le nœud %1</translation>
    </message>
    <message>
        <source>Delete node %1</source>
        <translation>Supprimer le nœud %1</translation>
    </message>
    <message>
        <source>Connect %1 to %2</source>
        <translation>Relier %1 à %2</translation>
    </message>
    <message>
        <source>Disconnect %1 from %2</source>
        <translation>Détacher %1 de %2</translation>
    </message>
    <message>
        <source>Make %1 the output</source>
        <translation>Faire de %1 la sortie</translation>
    </message>
    <message>
        <source>Move node %1</source>
        <translation>Déplacer le nœud %1</translation>
    </message>
    <message>
        <source>Apply preset %1</source>
        <translation>Appliquer le préréglage %1</translation>
    </message>
    <message>
        <source>Delete connection</source>
        <translation>Supprimer la liaison</translation>
    </message>
    <message>
        <source>Delete nodes</source>
        <translation>Supprimer les nœuds</translation>
    </message>
    <message>
        <source>Paste nodes</source>
        <translation>Coller les nœuds</translation>
    </message>
    <message>
        <source>Move nodes</source>
        <translation>Déplacer les nœuds</translation>
    </message>
    <message>
        <source>Change season</source>
        <translation>Changer la saison</translation>
    </message>
    <message>
        <source>Change tree season</source>
        <translation>Changer la saison de l&apos;arbre</translation>
    </message>
    <message>
        <source>Edit branch</source>
        <translation>Modifier la branche</translation>
    </message>
    <message>
        <source>Prune branch</source>
        <translation>Élaguer la branche</translation>
    </message>
    <message>
        <source>Clear branch edits</source>
        <translation>Effacer les modifications des branches</translation>
    </message>
    <message>
        <source>Change %1 (%2)</source>
        <translation>Modifier %1 (%2)</translation>
    </message>
</context>
<context>
    <name>Document</name>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
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
        <translation>arbre ▶</translation>
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
        <translation>%1 ms (en cache)</translation>
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
        <translation>%1&#xa0;: le nœud de sortie de l&apos;espèce n&apos;a produit aucun maillage</translation>
    </message>
    <message numerus="yes">
        <source>%1 (%n trees)</source>
        <translation>
            <numerusform>%1 (%n arbre)</numerusform>
            <numerusform>%1 (%n arbres)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: the project has no trees and no obstacles</source>
        <translation>%1&#xa0;: le projet ne contient ni arbres ni obstacles</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
</context>
<context>
    <name>TextureImage</name>
    <message>
        <source>Texture %1 cannot be read (%2); drawn without it</source>
        <translation>La texture %1 ne peut pas être lue (%2) ; dessiné sans elle</translation>
    </message>
    <message>
        <source>Texture %1 is %2 × %3 pixels, more than the %4 pixels (16384 × 16384) the editor decodes; drawn without it (exports copy it unchanged). Use a smaller texture.</source>
        <translation>La texture %1 fait %2 × %3 pixels, plus que les %4 pixels (16384 × 16384) que l’éditeur décode ; dessiné sans elle (les exports la copient telle quelle). Utilisez une texture plus petite.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Sylva, the procedural tree editor.</source>
        <translation>Sylva, l&apos;éditeur d&apos;arbres procéduraux.</translation>
    </message>
    <message>
        <source>Species or project (.sylva) to open (default: the ternary tree).</source>
        <translation>Espèce ou projet (.sylva) à ouvrir (par défaut&#xa0;: l&apos;arbre ternaire).</translation>
    </message>
    <message>
        <source>Render the viewport to &lt;file&gt; (PNG) and exit.</source>
        <translation>Rendre la vue dans &lt;file&gt; (PNG) et quitter.</translation>
    </message>
    <message>
        <source>Viewport size in pixels, e.g. 1024x768.</source>
        <translation>Taille de la vue en pixels, par ex. 1024x768.</translation>
    </message>
    <message>
        <source>Colour the tree by &lt;mode&gt;: material, light, vigour, age or order.</source>
        <translation>Colorer l&apos;arbre selon &lt;mode&gt;&#xa0;: material, light, vigour, age ou order.</translation>
    </message>
    <message>
        <source>Run the Python script &lt;file&gt; in the editor (after opening the project, if one is given) and exit with its status.</source>
        <translation>Exécuter le script Python &lt;file&gt; dans l&apos;éditeur (après l&apos;ouverture du projet, s&apos;il est indiqué) et quitter avec son code de sortie.</translation>
    </message>
    <message>
        <source>Restore edits autosaved before a crash without asking.</source>
        <translation>Restaurer sans confirmation les modifications enregistrées automatiquement avant un plantage.</translation>
    </message>
    <message>
        <source>Discard edits autosaved before a crash without asking.</source>
        <translation>Abandonner sans confirmation les modifications enregistrées automatiquement avant un plantage.</translation>
    </message>
    <message>
        <source>expected at most one species or project file</source>
        <translation>un seul fichier d&apos;espèce ou de projet est attendu au maximum</translation>
    </message>
    <message>
        <source>--size expects WxH between 16 and 8192, got &apos;%1&apos;</source>
        <translation>--size attend LxH entre 16 et 8192, reçu «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>--color-by expects material, light, vigour, age or order, got &apos;%1&apos;</source>
        <translation>--color-by attend material, light, vigour, age ou order, reçu «&#xa0;%1&#xa0;»</translation>
    </message>
</context>
<context>
    <name>sylva::doc::ProjectSettings</name>
    <message>
        <source>Wind direction</source>
        <translation>Direction du vent</translation>
    </message>
    <message>
        <source>Where the wind blows to, about the vertical: 0° along +X, 90° along +Z</source>
        <translation>Vers où souffle le vent, autour de la verticale : 0° selon +X, 90° selon +Z</translation>
    </message>
    <message>
        <source>Wind strength</source>
        <translation>Force du vent</translation>
    </message>
    <message>
        <source>0 calm, 1 strong, 2 storm: trees bend with its square</source>
        <translation>0 calme, 1 fort, 2 tempête : les arbres ploient avec son carré</translation>
    </message>
    <message>
        <source>Gustiness</source>
        <translation>Rafales</translation>
    </message>
    <message>
        <source>0 a steady wind, 1 gusts that double the pressure</source>
        <translation>0 un vent régulier, 1 des rafales qui doublent la pression</translation>
    </message>
    <message>
        <source>Sway frequency</source>
        <translation>Fréquence de balancement</translation>
    </message>
    <message>
        <source>How often the trunks sway; limbs, branches and leaves go faster</source>
        <translation>La fréquence d&apos;oscillation des troncs ; charpentières, branches et feuilles vont plus vite</translation>
    </message>
    <message>
        <source>Variants</source>
        <translation>Variantes</translation>
    </message>
    <message>
        <source>How many different trees of this species the forest is made of: a tree that touches no obstacle and no neighbour&apos;s crown shows one of them, turned and scaled; one that does is cut back from one of them. Fewer variants generate and export faster; 0 grows every tree for its place.</source>
        <translation>Combien d&apos;arbres différents de cette espèce composent la forêt : un arbre qui ne touche aucun obstacle ni la couronne d&apos;un voisin en montre un, tourné et mis à l&apos;échelle ; un arbre qui en touche est taillé à partir de l&apos;un d&apos;eux. Moins de variantes se génèrent et s&apos;exportent plus vite ; 0 fait pousser chaque arbre pour sa place.</translation>
    </message>
</context>
<context>
    <name>sylva::ui::BranchProperties</name>
    <message>
        <source>Branch %1</source>
        <translation>Branche %1</translation>
    </message>
    <message>
        <source>Edit:</source>
        <translation>Modification :</translation>
    </message>
    <message>
        <source>Length scale:</source>
        <translation>Facteur de longueur :</translation>
    </message>
    <message>
        <source>Scales the branch&apos;s own length about its base, 0.05 to 20; what it carries follows</source>
        <translation>Met à l’échelle la longueur propre de la branche autour de sa base, de 0,05 à 20 ; ce qu’elle porte suit</translation>
    </message>
    <message>
        <source>Radius scale:</source>
        <translation>Facteur de rayon :</translation>
    </message>
    <message>
        <source>Scales the thickness of the branch and what it carries, 0.05 to 20</source>
        <translation>Met à l’échelle l’épaisseur de la branche et de ce qu’elle porte, de 0,05 à 20</translation>
    </message>
    <message>
        <source>Locked: the branch and what it carries keep their exact shape when the species or the seed changes</source>
        <translation>Verrouillée : la branche et ce qu’elle porte gardent leur forme exacte quand l’espèce ou la graine change</translation>
    </message>
    <message>
        <source>Lock:</source>
        <translation>Verrouiller :</translation>
    </message>
    <message>
        <source>Prune</source>
        <translation>Élaguer</translation>
    </message>
    <message>
        <source>Removes the branch and everything it carries (Delete)</source>
        <translation>Supprime la branche et tout ce qu’elle porte (Suppr)</translation>
    </message>
    <message>
        <source>pruned</source>
        <translation>élaguée</translation>
    </message>
    <message>
        <source>bent</source>
        <translation>courbée</translation>
    </message>
    <message>
        <source>length ×%1</source>
        <translation>longueur ×%1</translation>
    </message>
    <message>
        <source>radius ×%1</source>
        <translation>rayon ×%1</translation>
    </message>
    <message>
        <source>locked</source>
        <translation>verrouillée</translation>
    </message>
    <message>
        <source>none (as grown)</source>
        <translation>aucune (telle que poussée)</translation>
    </message>
    <message>
        <source>Keep through regrowth</source>
        <translation>Garder à la repousse</translation>
    </message>
</context>
<context>
    <name>sylva::ui::ColorByMenu</name>
    <message>
        <source>&amp;Colour by</source>
        <translation>&amp;Colorer selon</translation>
    </message>
    <message>
        <source>&amp;Material</source>
        <translation>&amp;Matériau</translation>
    </message>
    <message>
        <source>&amp;Light (per internode)</source>
        <translation>&amp;Lumière (par entre-nœud)</translation>
    </message>
    <message>
        <source>&amp;Vigour</source>
        <translation>&amp;Vigueur</translation>
    </message>
    <message>
        <source>&amp;Age</source>
        <translation>Â&amp;ge</translation>
    </message>
    <message>
        <source>Branch &amp;order</source>
        <translation>&amp;Ordre des branches</translation>
    </message>
</context>
<context>
    <name>sylva::ui::CurveEditor</name>
    <message>
        <source>Drag a point to shape the curve; double-click to add a point; right-click or Delete removes one</source>
        <translation>Faites glisser un point pour modeler la courbe ; double-clic pour ajouter un point ; clic droit ou Suppr pour en retirer un</translation>
    </message>
</context>
<context>
    <name>sylva::ui::DocumentActions</name>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>&amp;Dupliquer</translation>
    </message>
    <message>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <source>Select &amp;all trees</source>
        <translation>Sélectionner &amp;tous les arbres</translation>
    </message>
    <message>
        <source>Add &amp;species from file…</source>
        <translation>Ajouter une &amp;espèce depuis un fichier…</translation>
    </message>
    <message>
        <source>Add &amp;tree</source>
        <translation>Ajouter un &amp;arbre</translation>
    </message>
    <message>
        <source>Ctrl+T</source>
        <translation>Ctrl+T</translation>
    </message>
    <message>
        <source>Import &amp;obstacle…</source>
        <translation>Importer un &amp;obstacle…</translation>
    </message>
    <message>
        <source>Add &amp;domain</source>
        <translation>Ajouter une &amp;zone</translation>
    </message>
    <message>
        <source>Add species</source>
        <translation>Ajouter une espèce</translation>
    </message>
    <message>
        <source>Species and grammars (*.json *.lsys *.txt);;All files (*)</source>
        <translation>Espèces et grammaires (*.json *.lsys *.txt);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Name in the project:</source>
        <translation>Nom dans le projet&#xa0;:</translation>
    </message>
    <message>
        <source>Import obstacle</source>
        <translation>Importer un obstacle</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.ply *.stl *.fbx *.gltf *.glb *.dae *.3ds *.off);;All files (*)</source>
        <translation>Maillages (*.obj *.ply *.stl *.fbx *.gltf *.glb *.dae *.3ds *.off);;Tous les fichiers (*)</translation>
    </message>
</context>
<context>
    <name>sylva::ui::DocumentGenerator</name>
    <message>
        <source>the generation failed</source>
        <translation>la génération a échoué</translation>
    </message>
</context>
<context>
    <name>sylva::ui::FileDialogs</name>
    <message>
        <source>Open species or project</source>
        <translation>Ouvrir une espèce ou un projet</translation>
    </message>
    <message>
        <source>Species, grammars and projects (*.json *.lsys *.txt *.sylva);;Projects (*.sylva);;All files (*)</source>
        <translation>Espèces, grammaires et projets (*.json *.lsys *.txt *.sylva);;Projets (*.sylva);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Save project as</source>
        <translation>Enregistrer le projet sous</translation>
    </message>
    <message>
        <source>Sylva projects (*.sylva)</source>
        <translation>Projets Sylva (*.sylva)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>Enregistrer une capture d&apos;écran</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.bmp)</source>
        <translation>Images (*.png *.jpg *.bmp)</translation>
    </message>
</context>
<context>
    <name>sylva::ui::GrammarEditor</name>
    <message>
        <source>Step through the derivation: the preview shows the tree after this many generations (the grammar keeps its own count)</source>
        <translation>Parcourir la dérivation pas à pas : l’aperçu montre l’arbre après ce nombre de générations (la grammaire garde le sien)</translation>
    </message>
    <message>
        <source>Animate</source>
        <translation>Animer</translation>
    </message>
    <message>
        <source>Play the derivation from the axiom to the last generation</source>
        <translation>Jouer la dérivation de l’axiome à la dernière génération</translation>
    </message>
    <message>
        <source>Symbols</source>
        <translation>Symboles</translation>
    </message>
    <message>
        <source>Generations:</source>
        <translation>Générations :</translation>
    </message>
    <message>
        <source>&lt;table cellspacing=4&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; f&lt;/td&gt;&lt;td&gt;move forward drawing / without drawing (length, m)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;+ -&lt;/b&gt;&lt;/td&gt;&lt;td&gt;turn left / right (angle, °)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;&amp;amp; ^&lt;/b&gt;&lt;/td&gt;&lt;td&gt;pitch down / up (°)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;\ /&lt;/b&gt;&lt;/td&gt;&lt;td&gt;roll left / right (°)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;|&lt;/b&gt;&lt;/td&gt;&lt;td&gt;turn around&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;[ ]&lt;/b&gt;&lt;/td&gt;&lt;td&gt;start / end a branch&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;!&lt;/b&gt;&lt;/td&gt;&lt;td&gt;width: set (diameter, m) or multiply by width_factor&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;$&lt;/b&gt; &lt;b&gt;%&lt;/b&gt;&lt;/td&gt;&lt;td&gt;roll left horizontal / cut the branch&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;J&lt;/b&gt;&lt;/td&gt;&lt;td&gt;a leaf (size, m)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;A B X …&lt;/td&gt;&lt;td&gt;other modules: state for the rules&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;a &amp;lt; B &amp;gt; c&lt;/td&gt;&lt;td&gt;context; &lt;b&gt;: cond&lt;/b&gt; before -&amp;gt;, &lt;b&gt;: weight&lt;/b&gt; after the successor&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table cellspacing=4&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; f&lt;/td&gt;&lt;td&gt;avancer en traçant / sans tracer (longueur, m)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;+ -&lt;/b&gt;&lt;/td&gt;&lt;td&gt;tourner à gauche / droite (angle, °)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;&amp;amp; ^&lt;/b&gt;&lt;/td&gt;&lt;td&gt;piquer / cabrer (°)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;\ /&lt;/b&gt;&lt;/td&gt;&lt;td&gt;rouler à gauche / droite (°)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;|&lt;/b&gt;&lt;/td&gt;&lt;td&gt;demi-tour&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;[ ]&lt;/b&gt;&lt;/td&gt;&lt;td&gt;début / fin d’une branche&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;!&lt;/b&gt;&lt;/td&gt;&lt;td&gt;largeur : fixer (diamètre, m) ou multiplier par width_factor&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;$&lt;/b&gt; &lt;b&gt;%&lt;/b&gt;&lt;/td&gt;&lt;td&gt;rouler à l’horizontale / couper la branche&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;J&lt;/b&gt;&lt;/td&gt;&lt;td&gt;une feuille (taille, m)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;A B X …&lt;/td&gt;&lt;td&gt;autres modules : état pour les règles&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;a &amp;lt; B &amp;gt; c&lt;/td&gt;&lt;td&gt;contexte ; &lt;b&gt;: condition&lt;/b&gt; avant -&amp;gt;, &lt;b&gt;: poids&lt;/b&gt; après le successeur&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Errors in the grammar: click one to jump to it</source>
        <translation>Erreurs de la grammaire : cliquer pour y aller</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>Select an lsystem node to edit its grammar.</source>
        <translation>Choisissez un nœud lsystem pour modifier sa grammaire.</translation>
    </message>
    <message>
        <source>Grammar of %1 · %2 (kept in the project)</source>
        <translation>Grammaire de %1 · %2 (gardée dans le projet)</translation>
    </message>
    <message>
        <source>Grammar of %1 · %2, read from %3; your edits are kept in the project, the file is not written</source>
        <translation>Grammaire de %1 · %2, lue dans %3 ; vos modifications sont gardées dans le projet, le fichier n’est pas écrit</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <translation>ligne %1, colonne %2 : %3</translation>
    </message>
    <message>
        <source>No errors</source>
        <translation>Aucune erreur</translation>
    </message>
    <message>
        <source>The rule that grew the branch you clicked in the preview</source>
        <translation>La règle qui a produit la branche cliquée dans l’aperçu</translation>
    </message>
</context>
<context>
    <name>sylva::ui::HelpMenu</name>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aide</translation>
    </message>
    <message>
        <source>&amp;Documentation</source>
        <translation>&amp;Documentation</translation>
    </message>
    <message>
        <source>&amp;About Sylva</source>
        <translation>À &amp;propos de Sylva</translation>
    </message>
    <message>
        <source>About Sylva</source>
        <translation>À propos de Sylva</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Sylva %1&lt;/h3&gt;&lt;p&gt;Procedural trees and forests for film and games: L-systems, space colonization and self-organizing trees, forests that react to the scene they stand in.&lt;/p&gt;&lt;p&gt;Scripting: Python (the Python Console, or &lt;tt&gt;sylva --script file.py&lt;/tt&gt;).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Sylva %1&lt;/h3&gt;&lt;p&gt;Arbres et forêts procéduraux pour le cinéma et le jeu vidéo&#xa0;: L-systèmes, colonisation de l&apos;espace et arbres auto-organisés, des forêts qui réagissent à la scène dans laquelle elles se trouvent.&lt;/p&gt;&lt;p&gt;Scripts&#xa0;: Python (la console Python, ou &lt;tt&gt;sylva --script file.py&lt;/tt&gt;).&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>sylva::ui::LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Langue du système</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Langue</translation>
    </message>
    <message>
        <source>Sylva will use the new language when it starts again.</source>
        <translation>Sylva utilisera la nouvelle langue au prochain démarrage.</translation>
    </message>
</context>
<context>
    <name>sylva::ui::LodChainExportAction</name>
    <message>
        <source>Export &amp;LOD chain…</source>
        <translation>Exporter la chaîne de &amp;LOD…</translation>
    </message>
    <message>
        <source>Writes the species&apos; or the selected tree&apos;s game LOD chain (LOD0 to LOD3 and the impostor as glTF, FBX, USD, OBJ and PNG maps) into a folder, as sylva-cli lods does</source>
        <translation>Écrit la chaîne de LOD de jeu de l’espèce ou de l’arbre sélectionné (LOD0 à LOD3 et l’imposteur en glTF, FBX, USD, OBJ et cartes PNG) dans un dossier, comme sylva-cli lods</translation>
    </message>
    <message>
        <source>Export LOD chain into folder</source>
        <translation>Exporter la chaîne de LOD dans le dossier</translation>
    </message>
    <message>
        <source>Select one tree, or open a species, to export its LOD chain.</source>
        <translation>Sélectionnez un arbre, ou ouvrez une espèce, pour en exporter la chaîne de LOD.</translation>
    </message>
    <message>
        <source>Exporting the LOD chain of %1…</source>
        <translation>Export de la chaîne de LOD de %1…</translation>
    </message>
    <message>
        <source>Export LOD chain</source>
        <translation>Exporter la chaîne de LOD</translation>
    </message>
    <message>
        <source>LOD chain export cancelled: nothing was written.</source>
        <translation>Export de la chaîne de LOD annulé : rien n’a été écrit.</translation>
    </message>
    <message>
        <source>Exported the LOD chain of %1 (%2 levels and the impostor) to %3</source>
        <translation>Chaîne de LOD de %1 (%2 niveaux et l’imposteur) exportée vers %3</translation>
    </message>
    <message numerus="yes">
        <source>; %n budget(s) left out: the tree has too few triangles for them</source>
        <translation>
            <numerusform>; %n budget omis : l’arbre a trop peu de triangles pour lui</numerusform>
            <numerusform>; %n budgets omis : l’arbre a trop peu de triangles pour eux</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>sylva::ui::MainWindow</name>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Stop the generation; the last result stays</source>
        <translation>Arrêter la génération&#xa0;; le dernier résultat est conservé</translation>
    </message>
    <message>
        <source>Generating: %1</source>
        <translation>Génération&#xa0;: %1</translation>
    </message>
    <message>
        <source>Regrowing: %1</source>
        <translation>Nouvelle croissance&#xa0;: %1</translation>
    </message>
    <message>
        <source>Generation cancelled; the last result stays</source>
        <translation>Génération annulée&#xa0;; le dernier résultat est conservé</translation>
    </message>
    <message>
        <source>Updated in %1 ms (edit to screen, %2 tree(s) regrown)</source>
        <translation>Mis à jour en %1 ms (de la modification à l&apos;affichage&#xa0;; arbres recalculés&#xa0;: %2)</translation>
    </message>
    <message>
        <source>Autosaved to %1</source>
        <translation>Enregistré automatiquement dans %1</translation>
    </message>
    <message>
        <source>Outliner</source>
        <translation>Synoptique</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <source>Statistics</source>
        <translation>Statistiques</translation>
    </message>
    <message>
        <source>&lt;opened&gt;</source>
        <translation>&lt;ouvert&gt;</translation>
    </message>
    <message>
        <source>Undo History</source>
        <translation>Historique d&apos;annulation</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Messages</translation>
    </message>
    <message>
        <source>Python Console</source>
        <translation>Console Python</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>&amp;New project</source>
        <translation>&amp;Nouveau projet</translation>
    </message>
    <message>
        <source>&amp;Open species or project…</source>
        <translation>&amp;Ouvrir une espèce ou un projet…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <source>Save &amp;as…</source>
        <translation>Enregistrer &amp;sous…</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>Re&amp;venir à la version enregistrée</translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation>&amp;Recharger</translation>
    </message>
    <message>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <source>Reload &amp;automatically</source>
        <translation>Recharger &amp;automatiquement</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>E&amp;xporter…</translation>
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
        <source>Save s&amp;creenshot…</source>
        <translation>Enregistrer une ca&amp;pture d&apos;écran…</translation>
    </message>
    <message>
        <source>Ctrl+Alt+S</source>
        <translation>Ctrl+Alt+S</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
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
        <translation>&amp;Scène</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>Show &amp;grid</source>
        <translation>Afficher la &amp;grille</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Panneaux</translation>
    </message>
    <message>
        <source>Colouring by node attributes needs a single tree: the forest is shown in its materials</source>
        <translation>La coloration selon les attributs des nœuds nécessite un seul arbre&#xa0;: la forêt est affichée avec ses matériaux</translation>
    </message>
    <message>
        <source>Generating %1…</source>
        <translation>Génération de %1…</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 ouvert</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <source>Revert to the saved file and lose your edits?</source>
        <translation>Revenir au fichier enregistré et perdre vos modifications&#xa0;?</translation>
    </message>
    <message>
        <source>No presets folder found: set SYLVA_PRESETS_DIR or open a species file with File ▸ Open species…</source>
        <translation>Aucun dossier de préréglages trouvé&#xa0;: définissez SYLVA_PRESETS_DIR ou ouvrez un fichier d&apos;espèce avec Fichier ▸ Ouvrir une espèce ou un projet…</translation>
    </message>
    <message>
        <source>Generated %1 in %2 ms</source>
        <translation>%1 généré en %2 ms</translation>
    </message>
    <message>
        <source>%1 (preview) — Sylva</source>
        <translation>%1 (aperçu) — Sylva</translation>
    </message>
    <message numerus="yes">
        <source>%1 (%n trees)</source>
        <translation>
            <numerusform>%1 (%n arbre)</numerusform>
            <numerusform>%1 (%n arbres)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1[*] — Sylva</source>
        <translation>%1[*] — Sylva</translation>
    </message>
    <message>
        <source>Sylva</source>
        <translation>Sylva</translation>
    </message>
    <message>
        <source>%1 has unsaved edits. Save them first?</source>
        <translation>%1 contient des modifications non enregistrées. Les enregistrer d&apos;abord&#xa0;?</translation>
    </message>
    <message>
        <source>an untitled project</source>
        <translation>projet sans titre</translation>
    </message>
    <message>
        <source>Sylva found edits of %1 autosaved at %2 that were never saved (the editor did not close normally). Restore them?</source>
        <translation>Sylva a trouvé des modifications de «&#xa0;%1&#xa0;» enregistrées automatiquement le %2 mais jamais enregistrées (l&apos;éditeur ne s&apos;est pas fermé normalement). Les restaurer&#xa0;?</translation>
    </message>
    <message>
        <source>Restored the autosaved edits of %1</source>
        <translation>Modifications de «&#xa0;%1&#xa0;» enregistrées automatiquement restaurées</translation>
    </message>
    <message>
        <source>%1 changed on disk. Reload it and lose your unsaved edits?</source>
        <translation>%1 a été modifié sur le disque. Le recharger et perdre vos modifications non enregistrées&#xa0;?</translation>
    </message>
    <message>
        <source>Could not read the viewport&apos;s image (no OpenGL context).</source>
        <translation>Impossible de lire l&apos;image de la vue (aucun contexte OpenGL).</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>Impossible d&apos;écrire %1.</translation>
    </message>
    <message>
        <source>Nothing to export yet.</source>
        <translation>Rien à exporter pour l&apos;instant.</translation>
    </message>
    <message>
        <source>Export with the project&apos;s wind</source>
        <translation>Exporter avec le vent du projet</translation>
    </message>
    <message>
        <source>When the project has a wind, File ▸ Export writes it as sylva-cli forest --wind: a rig and a looping wind clip per tree (.glb, .gltf, .fbx)</source>
        <translation>Si le projet a un vent, Fichier ▸ Exporter l&apos;écrit comme sylva-cli forest --wind : un squelette et une boucle de vent par arbre (.glb, .gltf, .fbx)</translation>
    </message>
    <message numerus="yes">
        <source>Exported %n tree(s) with the project&apos;s wind to %1 (%2 files)</source>
        <translation>
            <numerusform>%n arbre exporté avec le vent du projet vers %1 (%2 fichiers)</numerusform>
            <numerusform>%n arbres exportés avec le vent du projet vers %1 (%2 fichiers)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Exported %n tree(s) to %1 (%2 files)</source>
        <translation>
            <numerusform>%n arbre exporté vers %1 (%2 fichiers)</numerusform>
            <numerusform>%n arbres exportés vers %1 (%2 fichiers)</numerusform>
        </translation>
    </message>
    <message>
        <source>Export only the selection</source>
        <translation>Exporter uniquement la sélection</translation>
    </message>
    <message>
        <source>File ▸ Export writes only the selected trees</source>
        <translation>Fichier ▸ Exporter n&apos;écrit que les arbres sélectionnés</translation>
    </message>
    <message>
        <source>Export with the viewport camera&apos;s detail</source>
        <translation>Exporter avec le niveau de détail de la caméra de la vue</translation>
    </message>
    <message>
        <source>File ▸ Export chooses each tree&apos;s level of detail for the viewport&apos;s camera instead of the project&apos;s camera</source>
        <translation>Fichier ▸ Exporter choisit le niveau de détail de chaque arbre pour la caméra de la vue au lieu de la caméra du projet</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Préférences…</translation>
    </message>
    <message>
        <source>&amp;Frame selection or all</source>
        <translation>Cadrer la &amp;sélection ou tout</translation>
    </message>
    <message>
        <source>Species Editor</source>
        <translation>Éditeur d’espèces</translation>
    </message>
    <message>
        <source>Node Parameters</source>
        <translation>Paramètres du nœud</translation>
    </message>
    <message>
        <source>The project has no species to edit: add one from the Presets menu</source>
        <translation>Le projet n’a aucune espèce à modifier : ajoutez-en une depuis le menu Préréglages</translation>
    </message>
    <message>
        <source>&amp;Edit species…</source>
        <translation>&amp;Modifier l’espèce…</translation>
    </message>
    <message>
        <source>Preset Browser</source>
        <translation>Navigateur de préréglages</translation>
    </message>
    <message>
        <source>&amp;Wind</source>
        <translation>&amp;Vent</translation>
    </message>
    <message>
        <source>Trees sway in the project&apos;s wind (Properties, with nothing selected): the wind model the exports carry</source>
        <translation>Les arbres se balancent dans le vent du projet (Propriétés, sans sélection) : le modèle de vent que portent les exports</translation>
    </message>
    <message>
        <source>Species preview (%1): %2</source>
        <translation>Aperçu de l’espèce (%1) : %2</translation>
    </message>
    <message>
        <source>Generation failed: %1</source>
        <translation>Échec de la génération : %1</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>Exporting to %1…</source>
        <translation>Export vers %1…</translation>
    </message>
    <message>
        <source>Export cancelled: nothing was written.</source>
        <translation>Export annulé : rien n’a été écrit.</translation>
    </message>
</context>
<context>
    <name>sylva::ui::MessagesPanel</name>
    <message>
        <source>Clear</source>
        <translation>Effacer</translation>
    </message>
</context>
<context>
    <name>sylva::ui::NodeGraphScene</name>
    <message>
        <source>Added %1</source>
        <translation>%1 ajouté</translation>
    </message>
    <message>
        <source>Connected %1 to %2</source>
        <translation>%1 relié à %2</translation>
    </message>
    <message>
        <source>Disconnected %1 from %2</source>
        <translation>%1 détaché de %2</translation>
    </message>
    <message>
        <source>Deleted %1</source>
        <translation>%1 supprimé</translation>
    </message>
    <message>
        <source>a connection</source>
        <translation>une liaison</translation>
    </message>
    <message>
        <source>Pasted %1</source>
        <translation>%1 collé</translation>
    </message>
</context>
<context>
    <name>sylva::ui::NodeGraphView</name>
    <message>
        <source>Species graph: drag from a node&apos;s right port to another node to connect; Tab or right click adds a node; Delete removes; Ctrl+C/Ctrl+V copy and paste; F frames all</source>
        <translation>Graphe de l’espèce : tirer du port droit d’un nœud vers un autre pour les relier ; Tab ou clic droit ajoute un nœud ; Suppr supprime ; Ctrl+C/Ctrl+V copier-coller ; F cadre tout</translation>
    </message>
    <message>
        <source>Search node types…</source>
        <translation>Chercher un type de nœud…</translation>
    </message>
    <message>
        <source>%1  —  %2</source>
        <translation>%1  —  %2</translation>
    </message>
    <message>
        <source>Make it the tree (output)</source>
        <translation>En faire l’arbre (sortie)</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
</context>
<context>
    <name>sylva::ui::OutlinerModel</name>
    <message>
        <source>cannot read: %1</source>
        <translation>lecture impossible&#xa0;: %1</translation>
    </message>
    <message>
        <source>Species (%1)</source>
        <translation>Espèces (%1)</translation>
    </message>
    <message>
        <source>Trees (%1)</source>
        <translation>Arbres (%1)</translation>
    </message>
    <message>
        <source>Domains (%1)</source>
        <translation>Zones (%1)</translation>
    </message>
    <message>
        <source>Obstacles (%1)</source>
        <translation>Obstacles (%1)</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Lumière</translation>
    </message>
    <message>
        <source>Position %1, looking at %2: the LOD reference and the start view</source>
        <translation>Position %1, visant %2&#xa0;: la référence du LOD et la vue de départ</translation>
    </message>
    <message>
        <source>Light direction %1</source>
        <translation>Direction de la lumière %1</translation>
    </message>
    <message>
        <source>Stored in the project (edited here)</source>
        <translation>Stockée dans le projet (modifiée ici)</translation>
    </message>
    <message>
        <source>From %1</source>
        <translation>Source&#xa0;: %1</translation>
    </message>
    <message>
        <source>%1 #%2</source>
        <translation>%1 #%2</translation>
    </message>
    <message>
        <source>At %1 m, rotated %2°, scale %3, seed %4</source>
        <translation>À %1 m, pivoté de %2°, échelle %3, graine %4</translation>
    </message>
    <message>
        <source>%1 %2: %3 trees</source>
        <translation>%1 %2&#xa0;: %3 arbres</translation>
    </message>
    <message>
        <source>pruned</source>
        <translation>élaguée</translation>
    </message>
    <message>
        <source>bent</source>
        <translation>courbée</translation>
    </message>
    <message>
        <source>length ×%1</source>
        <translation>longueur ×%1</translation>
    </message>
    <message>
        <source>radius ×%1</source>
        <translation>rayon ×%1</translation>
    </message>
    <message>
        <source>locked</source>
        <translation>verrouillée</translation>
    </message>
    <message>
        <source>Branch %1: %2</source>
        <translation>Branche %1 : %2</translation>
    </message>
    <message>
        <source>%1 (orphaned)</source>
        <translation>%1 (orpheline)</translation>
    </message>
    <message>
        <source>The grown tree has no branch %1 now: the edit is kept and applies again when the branch grows back</source>
        <translation>L’arbre poussé n’a plus de branche %1 : la modification est gardée et s’applique de nouveau quand la branche repousse</translation>
    </message>
    <message>
        <source>A hand edit of branch %1 (Branch tool, doc.edit_branch)</source>
        <translation>Une retouche à la main de la branche %1 (outil Branche, doc.edit_branch)</translation>
    </message>
</context>
<context>
    <name>sylva::ui::ParameterPanel</name>
    <message>
        <source>&lt;i&gt;Select a node in the species graph to edit its parameters.&lt;/i&gt;</source>
        <translation>&lt;i&gt;Choisissez un nœud du graphe pour modifier ses paramètres.&lt;/i&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; — %2&lt;br&gt;&lt;small&gt;%3&lt;/small&gt;</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; — %2&lt;br&gt;&lt;small&gt;%3&lt;/small&gt;</translation>
    </message>
    <message>
        <source>%1
%2 · default %3%4</source>
        <translation>%1
%2 · défaut %3%4</translation>
    </message>
    <message>
        <source>unset</source>
        <translation>non défini</translation>
    </message>
    <message>
        <source> · range %1</source>
        <translation> · plage %1</translation>
    </message>
    <message>
        <source>Reset %1 to its default (%2)</source>
        <translation>Remettre %1 à sa valeur par défaut (%2)</translation>
    </message>
    <message>
        <source>relative to the project</source>
        <translation>relatif au projet</translation>
    </message>
    <message>
        <source>Choose a file</source>
        <translation>Choisir un fichier</translation>
    </message>
    <message>
        <source>Edit in the grammar editor</source>
        <translation>Modifier dans l’éditeur de grammaire</translation>
    </message>
    <message numerus="yes">
        <source>Edit in the grammar editor (%n lines)</source>
        <translation>
            <numerusform>Modifier dans l’éditeur de grammaire (%n ligne)</numerusform>
            <numerusform>Modifier dans l’éditeur de grammaire (%n lignes)</numerusform>
        </translation>
    </message>
    <message>
        <source>unset (JSON)</source>
        <translation>non défini (JSON)</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Appliquer</translation>
    </message>
    <message>
        <source>height, base → top</source>
        <translation>hauteur, base → sommet</translation>
    </message>
    <message>
        <source>radius (× the envelope radius)</source>
        <translation>rayon (× rayon de l’enveloppe)</translation>
    </message>
    <message>
        <source>Crown profile:</source>
        <translation>Profil de houppier :</translation>
    </message>
    <message>
        <source>Make the envelope a profile (a solid of revolution you can draw), starting from one of Weber and Penn&apos;s crown shapes</source>
        <translation>Faire de l’enveloppe un profil (un solide de révolution que l’on dessine), à partir d’une des formes de houppier de Weber et Penn</translation>
    </message>
    <message>
        <source>start from a shape…</source>
        <translation>partir d’une forme…</translation>
    </message>
    <message>
        <source>conical</source>
        <translation>conique</translation>
    </message>
    <message>
        <source>spherical</source>
        <translation>sphérique</translation>
    </message>
    <message>
        <source>hemispherical</source>
        <translation>hémisphérique</translation>
    </message>
    <message>
        <source>cylindrical</source>
        <translation>cylindrique</translation>
    </message>
    <message>
        <source>tapered cylindrical</source>
        <translation>cylindrique effilé</translation>
    </message>
    <message>
        <source>flame</source>
        <translation>en flamme</translation>
    </message>
    <message>
        <source>inverse conical</source>
        <translation>conique inversé</translation>
    </message>
    <message>
        <source>tend flame</source>
        <translation>tendant vers la flamme</translation>
    </message>
    <message>
        <source>t</source>
        <translation>t</translation>
    </message>
    <message>
        <source>value</source>
        <translation>valeur</translation>
    </message>
    <message>
        <source>Drag points; double-click adds one; right-click removes one.</source>
        <translation>Faites glisser les points ; double-clic pour en ajouter un ; clic droit pour en retirer un.</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Préférences</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>While there are unsaved edits, a recovery copy is written this often and a few seconds after the last edit. It never replaces your file.</source>
        <translation>Tant qu&apos;il reste des modifications non enregistrées, une copie de récupération est écrite à cet intervalle et quelques secondes après la dernière modification. Elle ne remplace jamais votre fichier.</translation>
    </message>
    <message>
        <source>Autosave every:</source>
        <translation>Enregistrement automatique toutes les&#xa0;:</translation>
    </message>
    <message>
        <source>Recovery folder:</source>
        <translation>Dossier de récupération&#xa0;:</translation>
    </message>
    <message>
        <source>Automatic (off on a software renderer)</source>
        <translation>Automatique (désactivé avec un rendu logiciel)</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Désactivé</translation>
    </message>
    <message>
        <source>2× multisampling</source>
        <translation>Multiéchantillonnage 2×</translation>
    </message>
    <message>
        <source>4× multisampling</source>
        <translation>Multiéchantillonnage 4×</translation>
    </message>
    <message>
        <source>8× multisampling</source>
        <translation>Multiéchantillonnage 8×</translation>
    </message>
    <message>
        <source>Smooths the edges in the 3D view. Without a graphics card (a software renderer) it makes every frame two to three times slower. Takes effect when Sylva starts next.</source>
        <translation>Lisse les contours dans la vue 3D. Sans carte graphique (rendu logiciel), chaque image devient deux à trois fois plus lente. Prend effet au prochain démarrage de Sylva.</translation>
    </message>
    <message>
        <source>Antialiasing:</source>
        <translation>Anticrénelage&#xa0;:</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PresetBrowser</name>
    <message>
        <source>Double-click a preset to apply it to the species</source>
        <translation>Double-cliquez sur un préréglage pour l’appliquer à l’espèce</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Appliquer</translation>
    </message>
    <message>
        <source>Save species as preset…</source>
        <translation>Enregistrer l’espèce comme préréglage…</translation>
    </message>
    <message>
        <source>Save species as preset</source>
        <translation>Enregistrer l’espèce comme préréglage</translation>
    </message>
    <message>
        <source>Species (*.json)</source>
        <translation>Espèces (*.json)</translation>
    </message>
    <message>
        <source>The project has no species to apply a preset to.</source>
        <translation>Le projet n’a aucune espèce à laquelle appliquer un préréglage.</translation>
    </message>
    <message>
        <source>Apply replaces the graph of species &lt;b&gt;%1&lt;/b&gt; (undoable).</source>
        <translation>Appliquer remplace le graphe de l’espèce &lt;b&gt;%1&lt;/b&gt; (annulable).</translation>
    </message>
    <message>
        <source>Applied %1 to %2</source>
        <translation>%1 appliqué à %2</translation>
    </message>
    <message>
        <source>Saved %1 as %2</source>
        <translation>%1 enregistré sous %2</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PresetsMenu</name>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Préréglages</translation>
    </message>
    <message>
        <source>No presets folder found (set SYLVA_PRESETS_DIR)</source>
        <translation>Aucun dossier de préréglages trouvé (définissez SYLVA_PRESETS_DIR)</translation>
    </message>
    <message>
        <source>No presets in %1</source>
        <translation>Aucun préréglage dans %1</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PropertiesPanel</name>
    <message>
        <source>Seed:</source>
        <translation>Graine&#xa0;:</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>Projet</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Fichier&#xa0;:</translation>
    </message>
    <message>
        <source>The project seed: domain trees take their seeds from it and their ids</source>
        <translation>La graine du projet&#xa0;: les arbres des zones calculent leur graine à partir de celle-ci et de leur identifiant</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>pas encore enregistré</translation>
    </message>
    <message>
        <source>Tree #%1</source>
        <translation>Arbre #%1</translation>
    </message>
    <message>
        <source>Species:</source>
        <translation>Espèce&#xa0;:</translation>
    </message>
    <message>
        <source>Position:</source>
        <translation>Position&#xa0;:</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Where the trunk meets the ground, metres</source>
        <translation>Point où le tronc touche le sol, en mètres</translation>
    </message>
    <message>
        <source>Rotation:</source>
        <translation>Rotation&#xa0;:</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>Turn about the vertical axis, degrees</source>
        <translation>Rotation autour de l&apos;axe vertical, en degrés</translation>
    </message>
    <message>
        <source>Scale:</source>
        <translation>Échelle&#xa0;:</translation>
    </message>
    <message>
        <source>Uniform size factor, 0.01 to 100</source>
        <translation>Facteur de taille uniforme, de 0,01 à 100</translation>
    </message>
    <message>
        <source>Growth:</source>
        <translation>Croissance&#xa0;:</translation>
    </message>
    <message>
        <source>Growth stage, 0.01 (sapling) to 1 (mature)</source>
        <translation>Stade de croissance, de 0,01 (jeune plant) à 1 (adulte)</translation>
    </message>
    <message>
        <source>The tree&apos;s own seed: another seed grows another tree of the species</source>
        <translation>La graine propre à l&apos;arbre&#xa0;: une autre graine fait pousser un autre arbre de la même espèce</translation>
    </message>
    <message>
        <source>Obstacle %1</source>
        <translation>Obstacle %1</translation>
    </message>
    <message>
        <source>Mesh:</source>
        <translation>Maillage&#xa0;:</translation>
    </message>
    <message>
        <source>Translate:</source>
        <translation>Translation&#xa0;:</translation>
    </message>
    <message>
        <source>Moves the mesh, metres</source>
        <translation>Déplace le maillage, en mètres</translation>
    </message>
    <message>
        <source>Rotate:</source>
        <translation>Rotation&#xa0;:</translation>
    </message>
    <message>
        <source>Rotation about x, then y, then z, degrees</source>
        <translation>Rotation autour de x, puis y, puis z, en degrés</translation>
    </message>
    <message>
        <source>Scale per axis</source>
        <translation>Échelle par axe</translation>
    </message>
    <message>
        <source>Domain %1 (%2)</source>
        <translation>Zone %1 (%2)</translation>
    </message>
    <message>
        <source>Minimum x, z:</source>
        <translation>Minimum x, z&#xa0;:</translation>
    </message>
    <message>
        <source>Corner of the rectangle on the ground</source>
        <translation>Coin du rectangle au sol</translation>
    </message>
    <message>
        <source>Maximum x, z:</source>
        <translation>Maximum x, z&#xa0;:</translation>
    </message>
    <message>
        <source>Opposite corner of the rectangle</source>
        <translation>Coin opposé du rectangle</translation>
    </message>
    <message>
        <source>%1 trees:</source>
        <translation>Arbres (%1)&#xa0;:</translation>
    </message>
    <message>
        <source>How many trees of this species the domain scatters</source>
        <translation>Nombre d&apos;arbres de cette espèce que la zone disperse</translation>
    </message>
    <message>
        <source>0 (every tree unique)</source>
        <translation>0 (chaque arbre unique)</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <source>Where the camera stands: the reference for level of detail</source>
        <translation>Position de la caméra&#xa0;: la référence pour le niveau de détail</translation>
    </message>
    <message>
        <source>Target:</source>
        <translation>Cible&#xa0;:</translation>
    </message>
    <message>
        <source>The point the camera looks at</source>
        <translation>Le point que vise la caméra</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Lumière</translation>
    </message>
    <message>
        <source>Direction:</source>
        <translation>Direction&#xa0;:</translation>
    </message>
    <message>
        <source>The direction sunlight travels (towards the ground: y &lt; 0); trees grow towards where it comes from</source>
        <translation>La direction dans laquelle se propage la lumière du soleil (vers le sol&#xa0;: y &lt; 0)&#xa0;; les arbres poussent vers sa provenance</translation>
    </message>
    <message>
        <source>Species</source>
        <translation>Espèce</translation>
    </message>
    <message>
        <source>Stored in the project.</source>
        <translation>Stockée dans le projet.</translation>
    </message>
    <message>
        <source>From %1 (stored in the project after its first edit).</source>
        <translation>Source&#xa0;: %1 (stockée dans le projet après sa première modification).</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Printemps</translation>
    </message>
    <message>
        <source>Summer</source>
        <translation>Été</translation>
    </message>
    <message>
        <source>Autumn</source>
        <translation>Automne</translation>
    </message>
    <message>
        <source>Winter</source>
        <translation>Hiver</translation>
    </message>
    <message>
        <source>Season:</source>
        <translation>Saison :</translation>
    </message>
    <message>
        <source>Species&apos; own (summer)</source>
        <translation>Celle de l&apos;espèce (été)</translation>
    </message>
    <message>
        <source>The time of year of every tree without a season of its own: deciduous species flush in spring, colour in autumn and are bare in winter; conifers and evergreens stay as they are</source>
        <translation>La saison de chaque arbre sans saison propre : les feuillus débourrent au printemps, se colorent en automne et sont nus en hiver ; les conifères et les persistants restent tels quels</translation>
    </message>
    <message>
        <source>Project&apos;s season</source>
        <translation>Saison du projet</translation>
    </message>
    <message>
        <source>This tree&apos;s own time of year, or the project&apos;s season</source>
        <translation>La saison propre de cet arbre, ou celle du projet</translation>
    </message>
    <message>
        <source>%1 (%2):</source>
        <translation>%1 (%2) :</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;%3 hand-placed tree(s). Rename it in the outliner; tune its graph and parameters in the Species Editor (Scene ▸ Edit species…, Ctrl+Shift+E).</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;%3 arbre(s) placé(s) à la main. Renommez-la dans l’outliner ; réglez son graphe et ses paramètres dans l’éditeur d’espèces (Scène ▸ Modifier l’espèce…, Ctrl+Maj+E).</translation>
    </message>
    <message>
        <source>:</source>
        <translation> :</translation>
    </message>
</context>
<context>
    <name>sylva::ui::PythonConsole</name>
    <message>
        <source>Python %1: sylva and doc = sylva.document() are ready. Try doc.trees(), doc.species() or doc.add_tree(doc.species()[0], (0, 0, 0)).</source>
        <translation>Python %1 : sylva et doc = sylva.document() sont prêts. Essayez doc.trees(), doc.species() ou doc.add_tree(doc.species()[0], (0, 0, 0)).</translation>
    </message>
</context>
<context>
    <name>sylva::ui::RecentFilesMenu</name>
    <message>
        <source>Open &amp;recent</source>
        <translation>Fichiers ré&amp;cents</translation>
    </message>
    <message>
        <source>No recent files</source>
        <translation>Aucun fichier récent</translation>
    </message>
</context>
<context>
    <name>sylva::ui::SpeciesWorkbench</name>
    <message>
        <source>Species:</source>
        <translation>Espèce :</translation>
    </message>
    <message>
        <source>Preview: %1 ms from the edit</source>
        <translation>Aperçu : %1 ms après la modification</translation>
    </message>
    <message>
        <source>Species preview: %1 ms from the edit to the new tree on screen</source>
        <translation>Aperçu de l’espèce : %1 ms de la modification au nouvel arbre à l’écran</translation>
    </message>
    <message>
        <source>Preview failed</source>
        <translation>Échec de l’aperçu</translation>
    </message>
    <message>
        <source>Evaluation %1 ms</source>
        <translation>Évaluation %1 ms</translation>
    </message>
    <message>
        <source>Click a branch or a leaf to select the node that grew it</source>
        <translation>Cliquez sur une branche ou une feuille pour choisir le nœud qui l’a fait pousser</translation>
    </message>
    <message>
        <source>A leaf card, grown by node %1</source>
        <translation>Une feuille, poussée par le nœud %1</translation>
    </message>
    <message>
        <source>A branch, grown by node %1</source>
        <translation>Une branche, poussée par le nœud %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Graph&lt;/b&gt; — how the species grows: Tab adds a node, drag from a right port to a node to connect, Delete removes</source>
        <translation>&lt;b&gt;Graphe&lt;/b&gt; — comment l’espèce pousse : Tab ajoute un nœud, tirer d’un port droit vers un nœud les relie, Suppr supprime</translation>
    </message>
    <message>
        <source>&lt;b&gt;Preview&lt;/b&gt; — one tree; click a branch to select the node that grew it and see its grammar rule</source>
        <translation>&lt;b&gt;Aperçu&lt;/b&gt; — un arbre ; cliquez sur une branche pour sélectionner le nœud qui l’a produite et voir sa règle de grammaire</translation>
    </message>
    <message>
        <source>A branch, grown by node %1: the rule on line %2</source>
        <translation>Une branche, produite par le nœud %1 : la règle de la ligne %2</translation>
    </message>
    <message>
        <source>A branch of the clicked tree, grown by node %1: the rule on line %2 (the preview shows that tree, before adaptation)</source>
        <translation>Une branche de l’arbre cliqué, produite par le nœud %1 : la règle de la ligne %2 (l’aperçu montre cet arbre avant adaptation)</translation>
    </message>
    <message>
        <source>%1, node &apos;%2&apos;</source>
        <translation>%1, nœud &apos;%2&apos;</translation>
    </message>
    <message>
        <source>Preview failed (%1) — showing the last good tree: %2</source>
        <translation>Échec de l’aperçu (%1) — le dernier arbre valide reste affiché : %2</translation>
    </message>
    <message>
        <source>Preview failed (%1): %2</source>
        <translation>Échec de l’aperçu (%1) : %2</translation>
    </message>
    <message>
        <source>Branch tool: click a branch of the tree to select it, drag it to bend it, Delete prunes it</source>
        <translation>Outil Branche : cliquez sur une branche de l’arbre pour la sélectionner, faites-la glisser pour la courber ; Suppr la taille</translation>
    </message>
</context>
<context>
    <name>sylva::ui::StatsPanel</name>
    <message>
        <source>File:</source>
        <translation>Fichier&#xa0;:</translation>
    </message>
    <message>
        <source>Trees:</source>
        <translation>Arbres&#xa0;:</translation>
    </message>
    <message>
        <source>Vertices:</source>
        <translation>Sommets&#xa0;:</translation>
    </message>
    <message>
        <source>Triangles:</source>
        <translation>Triangles&#xa0;:</translation>
    </message>
    <message>
        <source>Segments:</source>
        <translation>Segments&#xa0;:</translation>
    </message>
    <message>
        <source>Leaves:</source>
        <translation>Feuilles&#xa0;:</translation>
    </message>
    <message>
        <source>Height:</source>
        <translation>Hauteur&#xa0;:</translation>
    </message>
    <message>
        <source>Generation time:</source>
        <translation>Temps de génération&#xa0;:</translation>
    </message>
    <message>
        <source>CO₂ stored:</source>
        <translation>CO₂ stocké&#xa0;:</translation>
    </message>
    <message>
        <source>Selection:</source>
        <translation>Sélection&#xa0;:</translation>
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
        <source>%1 t</source>
        <translation>%1 t</translation>
    </message>
    <message>
        <source>nothing selected</source>
        <translation>aucune sélection</translation>
    </message>
    <message numerus="yes">
        <source>%n tree(s)</source>
        <translation>
            <numerusform>%n arbre</numerusform>
            <numerusform>%n arbres</numerusform>
        </translation>
    </message>
    <message>
        <source>; up to %1 m tall, DBH up to %2 cm; wood %3 m³, biomass %4 kg, CO₂ %5 kg</source>
        <translation>; jusqu&apos;à %1 m de haut, DHP jusqu&apos;à %2 cm&#xa0;; bois %3 m³, biomasse %4 kg, CO₂ %5 kg</translation>
    </message>
    <message>
        <source>Generating %1…</source>
        <translation>Génération de %1…</translation>
    </message>
    <message>
        <source>Wood, biomass:</source>
        <translation>Bois, biomasse&#xa0;:</translation>
    </message>
    <message>
        <source>A project&apos;s wood volume and dry biomass, and the trees&apos; mean DBH</source>
        <translation>Volume de bois et biomasse sèche d&apos;un projet, et DHP moyen des arbres</translation>
    </message>
    <message>
        <source>%1 m³, %2 t; mean DBH %3 cm</source>
        <translation>%1 m³, %2 t&#xa0;; DHP moyen %3 cm</translation>
    </message>
    <message>
        <source>Showing:</source>
        <translation>Affiché&#xa0;:</translation>
    </message>
    <message>
        <source>The species previewed, or the project and its tree count</source>
        <translation>L&apos;espèce en aperçu, ou le projet et son nombre d&apos;arbres</translation>
    </message>
</context>
<context>
    <name>sylva::ui::ToolController</name>
    <message>
        <source>That tree was scattered by domain %1: its counts and extent are in Properties</source>
        <translation>Cet arbre a été dispersé par la zone %1&#xa0;: le nombre d&apos;arbres et l&apos;étendue de la zone se trouvent dans Propriétés</translation>
    </message>
    <message>
        <source>Move tree</source>
        <translation>Déplacer l&apos;arbre</translation>
    </message>
    <message>
        <source>Move trees</source>
        <translation>Déplacer les arbres</translation>
    </message>
    <message>
        <source>Add a species first (Scene ▸ Add species from file…)</source>
        <translation>Ajoutez d&apos;abord une espèce (Scène ▸ Ajouter une espèce depuis un fichier…)</translation>
    </message>
    <message>
        <source>A tree cannot stand inside an obstacle&apos;s footprint: the move was refused</source>
        <translation>Un arbre ne peut pas se trouver dans l&apos;emprise au sol d&apos;un obstacle&#xa0;: le déplacement a été refusé</translation>
    </message>
    <message numerus="yes">
        <source>Paint %n tree(s)</source>
        <translation>
            <numerusform>Peindre %n arbre</numerusform>
            <numerusform>Peindre %n arbres</numerusform>
        </translation>
    </message>
    <message>
        <source>A tree cannot stand inside an obstacle&apos;s footprint</source>
        <translation>Un arbre ne peut pas se trouver dans l&apos;emprise au sol d&apos;un obstacle</translation>
    </message>
    <message>
        <source>A tree&apos;s scale must stay between 0.01 and 100: the change was refused</source>
        <translation>L’échelle d’un arbre doit rester entre 0,01 et 100&#xa0;: la modification a été refusée</translation>
    </message>
    <message>
        <source>Rotate tree</source>
        <translation>Tourner l’arbre</translation>
    </message>
    <message>
        <source>Rotate trees</source>
        <translation>Tourner les arbres</translation>
    </message>
    <message>
        <source>Scale tree</source>
        <translation>Mettre l’arbre à l’échelle</translation>
    </message>
    <message>
        <source>Scale trees</source>
        <translation>Mettre les arbres à l’échelle</translation>
    </message>
    <message>
        <source>No ground under the cursor: nothing planted; click where the ground is drawn</source>
        <translation>Pas de sol sous le curseur : rien n’a été planté ; cliquez là où le sol est dessiné</translation>
    </message>
    <message>
        <source>Only hand-placed trees take branch edits: this one was scattered by a domain</source>
        <translation>Seuls les arbres placés à la main acceptent les retouches de branches : celui-ci a été semé par un domaine</translation>
    </message>
    <message>
        <source>Branch %1 is locked: unlock it in Properties before bending it</source>
        <translation>La branche %1 est verrouillée : déverrouillez-la dans Propriétés avant de la courber</translation>
    </message>
</context>
<context>
    <name>sylva::ui::ToolOptionsBar</name>
    <message>
        <source>Tools</source>
        <translation>Outils</translation>
    </message>
    <message>
        <source>Select</source>
        <translation>Sélection</translation>
    </message>
    <message>
        <source>Click a tree or obstacle to select it (Shift adds, Ctrl toggles, Ctrl+drag draws a box); [ and ] step through the trees</source>
        <translation>Cliquez sur un arbre ou un obstacle pour le sélectionner (Maj ajoute, Ctrl inverse la sélection, Ctrl+glisser trace un rectangle)&#xa0;; [ et ] parcourent les arbres</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Déplacer</translation>
    </message>
    <message>
        <source>Drag selected trees along the ground (Ctrl+drag rotates, Shift+drag scales; arrow keys nudge). They re-adapt to the obstacles when you let go</source>
        <translation>Faites glisser les arbres sélectionnés sur le sol (Ctrl+glisser fait pivoter, Maj+glisser met à l&apos;échelle&#xa0;; les touches fléchées les décalent pas à pas). Ils se réadaptent aux obstacles quand vous relâchez</translation>
    </message>
    <message>
        <source>Place</source>
        <translation>Planter</translation>
    </message>
    <message>
        <source>Click the ground to plant a tree of the chosen species</source>
        <translation>Cliquez sur le sol pour planter un arbre de l&apos;espèce choisie</translation>
    </message>
    <message>
        <source>Brush</source>
        <translation>Pinceau</translation>
    </message>
    <message>
        <source>Paint trees of the species mix with the radius and density below; one stroke is one undo step</source>
        <translation>Peindre des arbres du mélange d&apos;espèces avec le rayon et la densité ci-dessous&#xa0;; un coup de pinceau correspond à une étape d&apos;annulation</translation>
    </message>
    <message>
        <source>Erase</source>
        <translation>Gomme</translation>
    </message>
    <message>
        <source>Remove the hand-placed trees the brush passes over</source>
        <translation>Supprimer les arbres placés à la main sur lesquels passe le pinceau</translation>
    </message>
    <message>
        <source> Species: </source>
        <translation> Espèce&#xa0;: </translation>
    </message>
    <message>
        <source>The species the Place tool plants, and the Brush when no mix is given</source>
        <translation>L&apos;espèce que plante l&apos;outil Planter, et que peint le pinceau si aucun mélange n&apos;est indiqué</translation>
    </message>
    <message>
        <source> Radius: </source>
        <translation> Rayon&#xa0;: </translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Brush and eraser radius, metres</source>
        <translation>Rayon du pinceau et de la gomme, en mètres</translation>
    </message>
    <message>
        <source> Density: </source>
        <translation> Densité&#xa0;: </translation>
    </message>
    <message>
        <source> /100 m²</source>
        <translation> /100 m²</translation>
    </message>
    <message>
        <source>Trees tried per 100 m² under the brush; spacing rules keep trunks out of each other&apos;s crowns and out of obstacles</source>
        <translation>Arbres tentés par 100 m² sous le pinceau&#xa0;; des règles d&apos;espacement tiennent les troncs hors des houppiers des autres arbres et hors des obstacles</translation>
    </message>
    <message>
        <source> Mix: </source>
        <translation> Mélange&#xa0;: </translation>
    </message>
    <message>
        <source>e.g. alder 70, ternary 30</source>
        <translation>par ex. alder 70, ternary 30</translation>
    </message>
    <message>
        <source>Species and weights the brush paints; empty: the chosen species</source>
        <translation>Espèces et poids que peint le pinceau&#xa0;; vide&#xa0;: l&apos;espèce choisie</translation>
    </message>
    <message>
        <source>Branch</source>
        <translation>Branche</translation>
    </message>
    <message>
        <source>Click a branch of a hand-placed tree to select it (its settings in Properties), drag it to bend it about its base, Delete prunes it; each is one undo step</source>
        <translation>Cliquez sur une branche d’un arbre placé à la main pour la sélectionner (ses réglages dans Propriétés), faites-la glisser pour la courber autour de sa base, Suppr l’élague ; chaque action est une étape d’annulation</translation>
    </message>
</context>
<context>
    <name>sylva::ui::Viewport</name>
    <message>
        <source>OpenGL 3.3 core profile is not available (got %1.%2).</source>
        <translation>Le profil core d&apos;OpenGL 3.3 n&apos;est pas disponible (obtenu&#xa0;: %1.%2).</translation>
    </message>
    <message>
        <source>The mesh has an index out of range; it is not drawn.</source>
        <translation>Le maillage contient un indice hors limites&#xa0;; il n&apos;est pas dessiné.</translation>
    </message>
</context>
</TS>
