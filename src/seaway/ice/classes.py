"""Ice classes: Russian Register (RS), IACS Polar Classes and Finnish-Swedish (FSICR), and the
mapping between them that the cost models use.

Sources and what is assumed:

* RS classes and their ice (concentration, thickness): Grinyak et al. 2022, Table 1 (after the Russian
  Maritime Register rules). `max_concentration` reads the table's words with the WMO
  nomenclature: open ice ("разреженный") up to 6/10, close ice ("сплоченный") up to 8/10,
  compact ice ("сплошной") 10/10.
* FSICR design level-ice thickness (IA Super 1.0 m, IA 0.8, IB 0.6, IC 0.4 m): Finnish-Swedish
  Ice Class Rules 2017, section 1.2; their POLARIS rows are in IMO MSC.1/Circ.1519 itself.
* Nominal equivalences from the IMO polar guidelines: IA Super ~ PC6 ~ RS Arc4 (old UL),
  IA ~ PC7 ~ RS Ice3 (old L1). IB ~ Ice2 (L2) and IC ~ Ice1 (L3) follow the same old-to-new RS
  renaming.
* ASSUMED (no source we hold settles them): RS Arc5-Arc9 and the icebreakers against the Polar
  Classes, and the thickness given to PC classes (that of their RS equivalent). Each
  direction takes the weaker end of the equivalence ranges quoted in the trade, so a converted
  class never overstates the ship: RS -> PC (`polaris_class`) Arc5 PC6, Arc6 PC5, Arc7 PC4,
  Arc8 PC3, Arc9 PC2, Icebreaker6 PC4, Icebreaker7 PC3, Icebreaker8 PC2, Icebreaker9 PC1;
  PC -> RS (`rs_class`) PC1 Arc9, PC2 Arc8, PC3 Arc7, PC4 Arc6, PC5 Arc5, PC6 Arc4, PC7 Ice3.
  The two maps are deliberately not inverse. `assumed` on each class says which parts of its
  row are assumptions.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import SeawayError


@dataclass(frozen=True)
class IceClass:
    """One ice class.

    name: canonical name ('Arc7', 'PC3', 'IA Super', 'none').
    system: 'RS' (Russian Register), 'IACS' (Polar Class), 'FSICR' (Finnish-Swedish), 'none'.
    h_pass: thickness of ice (m) the class may enter (RS: Grinyak et al. 2022 Table 1; FSICR: design
        thickness; PC: that of `rs_class`, assumed).
    max_concentration: tenths of ice concentration the class may enter independently (6 open,
        8 close, 10 compact; Grinyak et al. 2022 Table 1).
    rs_class: the RS class whose paper-000 impact table this class uses.
    polaris_class: the row of the POLARIS RIV table (MSC.1/Circ.1519) this class uses.
    assumed: which fields are assumptions rather than sourced (empty when none).
    """

    name: str
    system: str
    h_pass: float
    max_concentration: float
    rs_class: str
    polaris_class: str
    assumed: tuple = ()


_OPEN, _CLOSE, _COMPACT = 6.0, 8.0, 10.0


def _rs(name, conc, h, pc, pc_assumed=True):
    return IceClass(name, "RS", h, conc, name, pc, ("polaris_class",) if pc_assumed else ())


#: Every class (IceClass), by canonical name, weakest first within each system.
CLASSES = {
    c.name: c
    for c in [
        IceClass("none", "none", 0.0, 0.0, "none", "not ice strengthened"),
        # Russian Register, Grinyak et al. 2022 Table 1.
        _rs("Ice1", _OPEN, 0.4, "IC"),
        _rs("Ice2", _OPEN, 0.5, "IB"),
        _rs("Ice3", _OPEN, 0.7, "IA", pc_assumed=False),
        _rs("Arc4", _OPEN, 0.8, "IA Super", pc_assumed=False),
        _rs("Arc5", _OPEN, 1.0, "PC6"),
        _rs("Arc6", _OPEN, 1.3, "PC5"),
        _rs("Arc7", _CLOSE, 1.4, "PC4"),
        _rs("Arc8", _CLOSE, 2.1, "PC3"),
        _rs("Arc9", _COMPACT, 3.5, "PC2"),
        _rs("Icebreaker6", _COMPACT, 1.5, "PC4"),
        _rs("Icebreaker7", _COMPACT, 2.0, "PC3"),
        _rs("Icebreaker8", _COMPACT, 3.0, "PC2"),
        _rs("Icebreaker9", _COMPACT, 4.0, "PC1"),
        # IACS Polar Classes: RS equivalent and its thickness/concentration assumed.
        *[
            IceClass(f"PC{n}", "IACS", 0.0, 0.0, rs, f"PC{n}", ("h_pass", "max_concentration", "rs_class"))
            for n, rs in [
                (1, "Arc9"),
                (2, "Arc8"),
                (3, "Arc7"),
                (4, "Arc6"),
                (5, "Arc5"),
                (6, "Arc4"),
                (7, "Ice3"),
            ]
        ],
        # Finnish-Swedish: design thickness from FSICR; RS equivalent nominal (IMO guidelines).
        IceClass("IC", "FSICR", 0.4, _OPEN, "Ice1", "IC", ("rs_class",)),
        IceClass("IB", "FSICR", 0.6, _OPEN, "Ice2", "IB", ("rs_class",)),
        IceClass("IA", "FSICR", 0.8, _OPEN, "Ice3", "IA"),
        IceClass("IA Super", "FSICR", 1.0, _OPEN, "Arc4", "IA Super"),
    ]
}
# PC classes take thickness and concentration from their RS equivalent (assumed).
for _n in range(1, 8):
    _pc = CLASSES[f"PC{_n}"]
    _eq = CLASSES[_pc.rs_class]
    CLASSES[_pc.name] = IceClass(
        _pc.name, "IACS", _eq.h_pass, _eq.max_concentration, _pc.rs_class, _pc.polaris_class, _pc.assumed
    )

#: Other spellings accepted by get_class (case and spaces/underscores/hyphens are ignored too).
ALIASES = {
    "not ice strengthened": "none",
    "nis": "none",
    "ia super": "IA Super",
    "1a super": "IA Super",
    "1a": "IA",
    "1b": "IB",
    "1c": "IC",
    "icebraker6": "Icebreaker6",
    "icebraker7": "Icebreaker7",
    "icebraker8": "Icebreaker8",
    "icebraker9": "Icebreaker9",
}  # Grinyak et al. 2022's spelling


def _key(name: str) -> str:
    return "".join(ch for ch in name.lower() if ch not in " _-")


_LOOKUP = {_key(n): n for n in CLASSES} | {_key(a): n for a, n in ALIASES.items()}


def class_names(system: str | None = None) -> list:
    """Canonical class names (of one `system`: 'RS', 'IACS', 'FSICR', 'none'), in table order."""
    return [n for n, c in CLASSES.items() if system is None or c.system == system]


def get_class(ice_class) -> IceClass:
    """The IceClass for a name ('Arc7', 'arc7', 'PC 3', 'IA Super', '1A', 'none', ...) or an
    IceClass itself; ValueError naming the valid classes otherwise."""
    if isinstance(ice_class, IceClass):
        return ice_class
    name = _LOOKUP.get(_key(ice_class)) if isinstance(ice_class, str) else None
    if name is None:
        raise SeawayError(f"ice_class must be one of {class_names()}, got {ice_class!r}")
    return CLASSES[name]


def with_article(name: str) -> str:
    """The class name with its indefinite article, as it is spoken: "an Arc7", "an IA Super",
    "a PC6" (P is read "pee")."""
    return f"{'an' if name[:1].upper() in 'AEIOU' else 'a'} {name}"
