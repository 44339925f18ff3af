"""The RatBez workbench's translations (issue 25): the template holds every translatable string of the Mod
folder, each language file follows it, and each compiled .qm gives the translations its .ts holds (read by
Qt's own QTranslator, as FreeCAD loads them). English makes the property group read "RatBez"."""
import pathlib
import re
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
TOOL = ROOT / "freecad_workbench" / "update_translations.py"
TRANSLATIONS = ROOT / "freecad_workbench" / "RatBez" / "Resources" / "translations"


def test_template_and_language_files_are_current():
    run = subprocess.run([sys.executable, str(TOOL), "--check"], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr


def finished(ts):
    root = ElementTree.parse(ts).getroot()
    for context in root.iter("context"):
        for message in context.iter("message"):
            translation = message.find("translation")
            if translation is not None and translation.get("type") is None and translation.text:
                yield context.findtext("name"), message.findtext("source"), translation.text


@pytest.mark.parametrize("language", ["en", "de"])
def test_compiled_translations_match_their_sources(language):
    QtCore = pytest.importorskip("PySide2.QtCore")
    translator = QtCore.QTranslator()
    assert translator.load(str(TRANSLATIONS / "RatBez_{}.qm".format(language)))
    messages = list(finished(TRANSLATIONS / "RatBez_{}.ts".format(language)))
    assert messages
    for context, source, translation in messages:
        # lrelease -removeidentical leaves out a translation equal to its source: Qt then shows the source.
        assert (translator.translate(context, source) or source) == translation, (context, source)


def test_english_turns_the_split_group_name_back_and_german_translates_the_commands():
    texts = {(c, s): t for c, s, t in finished(TRANSLATIONS / "RatBez_en.ts")}
    assert texts == {("App::Property", "Rat Bez"): "RatBez"}
    german = {(c, s): t for c, s, t in finished(TRANSLATIONS / "RatBez_de.ts")}
    assert german[("App::Property", "Rat Bez")] == "RatBez"
    assert german[("RatBez_Cone", "Cone")] == "Kegel"
    # Every string in German, each keeping its source's placeholders ({}, {:g}, %1) in order.
    sources = [m.findtext("source") for m in ElementTree.parse(TRANSLATIONS / "RatBez_de.ts").iter("message")]
    untranslated = sorted(set(sources) - {s for _, s in german})
    assert not untranslated, "{} German strings unfinished: {}".format(len(untranslated), untranslated[:3])
    placeholders = re.compile(r"\{[^{}]*\}|%\d+")
    mismatched = [s for (_, s), t in german.items() if placeholders.findall(s) != placeholders.findall(t)]
    assert not mismatched, "German placeholders differ from the source: {}".format(mismatched[:3])
