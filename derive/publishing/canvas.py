"""The Canvas export: a QTI 1.2 zip that Canvas imports as a graded quiz (derive.publishing.lms
says what both LMS exports share: the items, their tolerances in the units each LMS grades right,
the questions' HTML and the worked solutions as feedback).

A question group (a `<section>` that picks 1) per problem and asked quantity, with one item per
variant worth `POINTS` points, in a graded quiz (`assessment_meta.xml`, quiz type `assignment`).
An item is numerical (the answer and its margin, in a scaled unit where Canvas's four decimal
places need one) or multiple choice, each wrong choice's feedback naming the mistake that gives it.

>>> identifier("quiz", "demo", 4) == identifier("quiz", "demo", 4)
True
"""
from __future__ import annotations

import hashlib
import io
import zipfile
from decimal import Decimal
from typing import Mapping

from lxml import etree
from lxml.builder import ElementMaker

from derive.publishing.figure_files import FOLDER, Image
from derive.publishing.lms import (Item, _exponent, _feedback, _figure, _label, _mathjax, _paragraphs, _questions, _xml, choice_text, choices, scaled, scaled_unit)


# Canvas's QTI import, as this export relies on it (canvas-lms, and the packages it reads as its own):
# - the package: lib/cc/qti/qti_generator.rb (generate_quiz, generate_qti_only) writes a quiz as
#   ID/ID.xml, a resource of type imsqti_xmlv1p2 with a <dependency> on a second resource, of type
#   associatedcontent/imscc_xmlv1p1/learning-application-resource, whose file is
#   ID/assessment_meta.xml; ID is the resource's identifier and the assessment's ident. text2qti
#   (qti.py, xml_imsmanifest.py, xml_assessment_meta.py) and R/exams (exams2canvas ->
#   exams2qti12, inst/xml/canvas_manifest.xml, canvas_meta.xml) write the same layout.
# - the metadata: lib/cc/importer/canvas/quiz_metadata_converter.rb (post_process_assessments)
#   reads only a learning-application-resource's file named ASSESSMENT_ID/assessment_meta.xml,
#   then its quiz_type, points_possible, allowed_attempts ... and <assignment> (the gradebook
#   column); quiz_type "assignment" is a graded quiz.
# - the groups: gems/plugins/qti_exporter/lib/qti/assessment_test_converter.rb (process_section)
#   makes a section with a selection into a question group that picks that many, worth
#   points_per_item each; qti_generator.rb (add_group) writes it as
#   <selection_ordering><selection><selection_number>/<selection_extension><points_per_item>.
# - the items: lib/cc/qti/qti_items.rb (add_question) writes the fields question_type and
#   points_possible in itemmetadata, and a question's general feedback as
#   <itemfeedback ident="general_fb"> shown by a first respcondition (<other/>, continue Yes);
#   assessment_item_converter.rb (get_feedback) reads an ident matching general_ as the
#   question's neutral comments. Canvas typesets \( \) and \[ \] math with MathJax (exams2canvas
#   converts with "pandoc-mathjax" for it).
# - the figures: a file of the package is a resource of type webcontent listing it (text2qti:
#   xml_imsmanifest.py IMAGE, a resource per image with its <file>; markdown.py Image, whose src is
#   $IMS-CC-FILEBASE$/images/NAME), referred to from the HTML as $IMS-CC-FILEBASE$/PATH
#   (lib/cc/cc_helper.rb WEB_CONTENT_TOKEN); Canvas's link migrator (canvas_link_migrator,
#   link_parser.rb convert_link and parse_url) reads `$IMS-CC-FILEBASE$/(.*)` (or its %24-escaped
#   form) as a link to the imported file at that path.
QTI_NAMESPACE = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2"
MANIFEST_NAMESPACE = "http://www.imsglobal.org/xsd/imsccv1p1/imscp_v1p1"
CANVAS_NAMESPACE = "http://canvas.instructure.com/xsd/cccv1p0"
QTI = ElementMaker(namespace=QTI_NAMESPACE, nsmap={None: QTI_NAMESPACE})
MANIFEST = ElementMaker(namespace=MANIFEST_NAMESPACE, nsmap={None: MANIFEST_NAMESPACE})
CANVAS = ElementMaker(namespace=CANVAS_NAMESPACE, nsmap={None: CANVAS_NAMESPACE})
QTI_RESOURCE = "imsqti_xmlv1p2"
META_RESOURCE = "associatedcontent/imscc_xmlv1p1/learning-application-resource"
FIGURE_RESOURCE = "webcontent"
POINTS = 1  # an asked quantity's points, as a Moodle cloze field's default weight
GROUP_TITLE_LIMIT = 255  # characters of a Canvas question group's name


def identifier(*parts: object) -> str:
    """An identifier for Canvas, from what names the thing (set, seed, problem, variant, ...): the
    same in every export of the same set and seed, different for anything else, so that a second
    import matches its own quiz and questions and no other export's.

    >>> identifier("quiz", "demo", 4) == identifier("quiz", "demo", 4) != identifier("quiz", "demo", 5)
    True
    """
    return "d" + hashlib.sha256("\x1f".join(map(str, parts)).encode()).hexdigest()[:32]


def _field(label: str, entry: str) -> etree._Element:
    return QTI.qtimetadatafield(QTI.fieldlabel(label), QTI.fieldentry(entry))


def _numerical(item: Item, k: int) -> tuple[str, str, etree._Element, etree._Element]:
    """(question type, prompt, response, correct condition, feedback by choice: none): the answer, or
    within its margin, in the question's unit 10^-k UNIT."""
    (value, margin), unit = scaled(item.value, item.tolerance, k), scaled_unit(item.unit, k)
    low, high = Decimal(value) - Decimal(margin), Decimal(value) + Decimal(margin)
    response = QTI.response_str(QTI.render_fib(QTI.response_label(ident="answer1"), fibtype="Decimal"),
                                ident="response1", rcardinality="Single")
    within = QTI("and", QTI.vargte(str(low), respident="response1"), QTI.varlte(str(high), respident="response1"))
    condition = QTI("or", QTI.varequal(value, respident="response1"), within)
    return "numerical_question", f"{_label(item)} (in {unit})" if unit else _label(item), response, condition, {}


def _multiple_choice(item: Item, k: int) -> tuple[str, str, etree._Element, etree._Element, dict[str, str]]:
    """(question type, prompt, response, correct condition, feedback by choice): the right choice
    among the wrong, each a value as text in the question's unit 10^-k UNIT (`choice_text`), each
    wrong one with the mistake that gives it."""
    options = choices(item)
    labels = (QTI.response_label(QTI.material(QTI.mattext(choice_text(v, item.unit, k), texttype="text/plain")),
                                 ident=f"choice{n}")
              for n, (v, _, _) in enumerate(options))
    response = QTI.response_lid(QTI.render_choice(*labels), ident="response1", rcardinality="Single")
    (right,) = [n for n, (_, is_right, _) in enumerate(options) if is_right]
    return ("multiple_choice_question", _label(item), response, QTI.varequal(f"choice{right}", respident="response1"),
            {f"choice{n}": why for n, (_, _, why) in enumerate(options) if why})


def _direction(item: Item) -> tuple[str, str, etree._Element, etree._Element, dict[str, str]]:
    """(question type, prompt, response, correct condition, feedback by choice: none): which way the
    quantity points, one of the ways it can (`Item.senses`), where they differ between variants."""
    labels = (QTI.response_label(QTI.material(QTI.mattext(sense, texttype="text/plain")), ident=f"choice{n}")
              for n, sense in enumerate(item.senses))
    response = QTI.response_lid(QTI.render_choice(*labels), ident="response1", rcardinality="Single")
    right = item.senses.index(item.direction)
    return ("multiple_choice_question", f"{item.meaning}: which way does it point?", response,
            QTI.varequal(f"choice{right}", respident="response1"), {})


def _qti_item(item: Item, k: int, ident: str, figure: str = "", solution: str = "",
              direction: bool = False) -> etree._Element:
    """A Canvas item: its question type and points, the question's HTML (with the problem's
    `figure`, HTML), the response (numerical in the question's unit 10^-k UNIT), its scoring and
    the worked solution (`solution`, HTML: the item's, its images resolved) as general feedback; a
    wrong choice's feedback (`{choice}_fb`, as text2qti writes it and Canvas's
    assessment_item_converter reads it) names its mistake."""
    kind, prompt, response, condition, mistaken = (_direction(item) if direction else _multiple_choice(item, k)
                                                   if item.wrong else _numerical(item, k))
    text = _paragraphs(_mathjax(item.question)) + figure + _paragraphs(prompt)
    scoring = [QTI.respcondition(QTI.conditionvar(condition), QTI.setvar("100", action="Set", varname="SCORE"),
                                 {"continue": "No"})]
    feedback = []
    for choice, why in mistaken.items():
        scoring.insert(0, QTI.respcondition(QTI.conditionvar(QTI.varequal(choice, respident="response1")),
                                            QTI.displayfeedback(feedbacktype="Response", linkrefid=f"{choice}_fb"),
                                            {"continue": "Yes"}))
        feedback.append(QTI.itemfeedback(QTI.flow_mat(QTI.material(QTI.mattext(why, texttype="text/plain"))),
                                         ident=f"{choice}_fb"))
    if solution:
        scoring.insert(0, QTI.respcondition(QTI.conditionvar(QTI.other()),
                                            QTI.displayfeedback(feedbacktype="Response", linkrefid="general_fb"),
                                            {"continue": "Yes"}))
        feedback.append(QTI.itemfeedback(QTI.flow_mat(QTI.material(QTI.mattext(solution, texttype="text/html"))),
                                         ident="general_fb"))
    return QTI.item(
        QTI.itemmetadata(QTI.qtimetadata(_field("question_type", kind), _field("points_possible", str(POINTS)))),
        QTI.presentation(QTI.material(QTI.mattext(text, texttype="text/html")), response),
        QTI.resprocessing(QTI.outcomes(QTI.decvar(maxvalue="100", minvalue="0", varname="SCORE", vartype="Decimal")),
                          *scoring),
        *feedback,
        ident=ident, title=f"{item.problem} v{item.variant} {item.name}{' direction' if direction else ''}")


def qti(items: list[Item], title: str, set_id: str, seed: int, figures: Mapping[str, Image] = {}) -> bytes:
    """A QTI 1.2 zip for Canvas: a graded quiz with a question group per problem and asked
    quantity that picks one of its variants (numerical or multiple-choice items, worth POINTS
    each), its metadata (assessment_meta.xml), the problems' figures (`figures`, by problem id;
    figures/ID.png) and the free-body diagrams the feedback shows (figures/NAME.png, by name), and
    imsmanifest.xml listing them all.

    Canvas picks each group's item on its own, so a problem that asks for several quantities is one
    group per quantity: a Canvas item holds one numeric answer with a tolerance."""
    quiz = identifier("quiz", set_id, seed)
    groups = _questions(items)
    titles = {item.problem: item.title for item in items}
    paths = {problem: f"{FOLDER}/{figures[problem].file('png')}" for problem in titles if problem in figures}
    shown = {problem: _figure(f"$IMS-CC-FILEBASE$/{path}", figures[problem], titles[problem])
             for problem, path in paths.items()}
    solutions: dict[str, str] = {}  # each worked solution's HTML for Canvas, its diagrams' paths added to `paths`
    for item in items:
        if item.solution not in solutions:
            solutions[item.solution], diagrams = _feedback(item.solution, figures,
                                                           lambda image: f"$IMS-CC-FILEBASE$/{FOLDER}/{image.file('png')}")
            paths.update({image.name: f"{FOLDER}/{image.file('png')}" for image in diagrams})
    sections = [
        QTI.section(
            QTI.selection_ordering(QTI.selection(QTI.selection_number("1"),
                                                 QTI.selection_extension(QTI.points_per_item(str(POINTS))))),
            *(_qti_item(i, k, identifier("item", set_id, seed, problem, i.variant, name), shown.get(problem, ""),
                        solutions[i.solution]) for i in group),
            ident=identifier("group", set_id, seed, problem, name),
            title=f"{group[0].title}: {group[0].meaning}"[:GROUP_TITLE_LIMIT])
        for (problem, name), group in groups.items() for k in [_exponent(group, "qti")]]
    sections += [  # where the way a quantity points differs between variants, a group that asks it
        QTI.section(
            QTI.selection_ordering(QTI.selection(QTI.selection_number("1"),
                                                 QTI.selection_extension(QTI.points_per_item(str(POINTS))))),
            *(_qti_item(i, 0, identifier("item", set_id, seed, problem, i.variant, name, "direction"),
                        shown.get(problem, ""), solutions[i.solution], direction=True) for i in group),
            ident=identifier("group", set_id, seed, problem, name, "direction"),
            title=f"{group[0].title}: {group[0].meaning}, direction"[:GROUP_TITLE_LIMIT])
        for (problem, name), group in groups.items() if group[0].senses]
    assessment = QTI.questestinterop(QTI.assessment(QTI.section(*sections, ident="root_section"),
                                                    ident=quiz, title=title))
    points = str(POINTS * len(sections))
    meta = CANVAS.quiz(
        CANVAS.title(title), CANVAS.description(""), CANVAS.shuffle_answers("false"),
        CANVAS.scoring_policy("keep_highest"), CANVAS.quiz_type("assignment"), CANVAS.points_possible(points),
        CANVAS.show_correct_answers("true"), CANVAS.allowed_attempts("1"), CANVAS.one_question_at_a_time("false"),
        CANVAS.cant_go_back("false"), CANVAS.available("false"),
        CANVAS.assignment(CANVAS.title(title), CANVAS.workflow_state("unpublished"), CANVAS.quiz_identifierref(quiz),
                          CANVAS.points_possible(points), CANVAS.grading_type("points"),
                          CANVAS.submission_types("online_quiz"), identifier=identifier("assignment", set_id, seed)),
        identifier=quiz)
    assessment_path, meta_path = f"{quiz}/{quiz}.xml", f"{quiz}/assessment_meta.xml"
    meta_id = identifier("metadata", set_id, seed)
    manifest = MANIFEST.manifest(
        MANIFEST.metadata(MANIFEST.schema("IMS Content"), MANIFEST.schemaversion("1.1.3")),
        MANIFEST.organizations(),
        MANIFEST.resources(
            MANIFEST.resource(MANIFEST.file(href=assessment_path), MANIFEST.dependency(identifierref=meta_id),
                              identifier=quiz, type=QTI_RESOURCE),
            MANIFEST.resource(MANIFEST.file(href=meta_path), identifier=meta_id, type=META_RESOURCE, href=meta_path),
            *(MANIFEST.resource(MANIFEST.file(href=path), identifier=identifier("figure", set_id, seed, name),
                                type=FIGURE_RESOURCE, href=path) for name, path in paths.items())),
        identifier=identifier("manifest", set_id, seed))
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:  # stored, as ZipInfo entries are by default
        files = [("imsmanifest.xml", _xml(manifest)), (assessment_path, _xml(assessment)), (meta_path, _xml(meta)),
                 *((path, figures[name].png) for name, path in paths.items())]
        for name, data in files:
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))  # the same bytes every build
            archive.writestr(info, data)
    return buffer.getvalue()
