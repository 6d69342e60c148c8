"""References as data, and a record of which ones a run used.

Each model function names its sources with :func:`cites`; calling it records the keys,
so a run can list the papers it rests on (:func:`used_references`), as PyBaMM's
``print_citations`` does. Add new sources to :data:`REFERENCES`.

Work done elsewhere (a Dask worker process computing a study or map point) records its keys
in that process: :func:`collect_references` gathers the keys one piece of work used (in this
thread), so that the worker can return them with the result, and :func:`record_references`
adds returned keys to this process's record.
"""

from __future__ import annotations

import contextlib
import functools
import threading

REFERENCES: dict[str, str] = {
    "thesis": (
        "N. S. T. Almuramady, 'Dry friction between rough surfaces of silicon and functionalized gear "
        "microelectromechanical systems', PhD thesis, Cardiff University. Equation numbers such as (3-7) in "
        "memstribo's docstrings are this thesis's."
    ),
    "model": "memstribo's specification, docs/model.md (decisions where the thesis is ambiguous).",
    "borodich_savencu_2017": (
        "F. M. Borodich, O. Savencu, 'Hierarchical models of engineering rough surfaces and bio-inspired "
        "adhesives', in Bio-inspired Structured Adhesives, Springer, 2017. doi:10.1007/978-3-319-59114-8_10"
    ),
    "borodich_2014": (
        "F. M. Borodich, 'The Hertz-type and adhesive contact problems for depth-sensing indentation', "
        "Adv. Appl. Mech. 47 (2014) 225-366. doi:10.1016/B978-0-12-800130-1.00003-5"
    ),
    "galin_1961": "L. A. Galin, Contact Problems in the Theory of Elasticity, 1953; transl. NC State College, 1961.",
    "sneddon_1965": (
        "I. N. Sneddon, 'The relation between load and penetration in the axisymmetric Boussinesq problem "
        "for a punch of arbitrary profile', Int. J. Eng. Sci. 3 (1965) 47-57. doi:10.1016/0020-7225(65)90019-4"
    ),
    "johnson_1985": "K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985. doi:10.1017/CBO9781139171731",
    "hamilton_1983": (
        "G. M. Hamilton, 'Explicit equations for the stresses beneath a sliding spherical contact', "
        "Proc. IMechE C 197 (1983) 53-59. doi:10.1243/PIME_PROC_1983_197_076_02"
    ),
    "polonsky_keer_1999": (
        "I. A. Polonsky, L. M. Keer, 'A numerical method for solving rough contact problems based on the "
        "multi-level multi-summation and conjugate gradient techniques', Wear 231 (1999) 206-219. "
        "doi:10.1016/S0043-1648(99)00113-1"
    ),
    "maugis_1992": (
        "D. Maugis, 'Adhesion of spheres: the JKR-DMT transition using a Dugdale model', "
        "J. Colloid Interface Sci. 150 (1992) 243-269. doi:10.1016/0021-9797(92)90285-T"
    ),
    "dugdale_1960": (
        "D. S. Dugdale, 'Yielding of steel sheets containing slits', J. Mech. Phys. Solids 8 (1960) 100-104. "
        "doi:10.1016/0022-5096(60)90013-2"
    ),
    "turon_2007": (
        "A. Turon, C. G. Davila, P. P. Camanho, J. Costa, 'An engineering solution for mesh size effects in the "
        "simulation of delamination using cohesive zone models', Eng. Fract. Mech. 74 (2007) 1665-1682. "
        "doi:10.1016/j.engfracmech.2006.08.025"
    ),
    "rey_2017": (
        "V. Rey, G. Anciaux, J.-F. Molinari, 'Normal adhesive contact on rough surfaces: efficient algorithm for "
        "FFT-based BEM resolution', Comput. Mech. 60 (2017) 69-81. doi:10.1007/s00466-017-1392-5"
    ),
    "bazrafshan_2017": (
        "M. Bazrafshan, M. B. de Rooij, M. Valefi, D. J. Schipper, 'Numerical method for the adhesive normal "
        "contact analysis based on a Dugdale approximation', Tribol. Int. 112 (2017) 117-128. "
        "doi:10.1016/j.triboint.2017.04.001"
    ),
    "baney_hui_1997": (
        "J. M. Baney, C.-Y. Hui, 'A cohesive zone model for the adhesion of cylinders', J. Adhes. Sci. Technol. "
        "11 (1997) 393-406. doi:10.1163/156856197X00822"
    ),
    "johnson_greenwood_2008": (
        "K. L. Johnson, J. A. Greenwood, 'A Maugis analysis of adhesive line contact', J. Phys. D: Appl. Phys. "
        "41 (2008) 155315. doi:10.1088/0022-3727/41/15/155315"
    ),
    "kendall_1971": (
        "K. Kendall, 'The adhesion and surface energy of elastic solids', J. Phys. D 4 (1971) 1186. "
        "doi:10.1088/0022-3727/4/8/320"
    ),
    "israelachvili_2011": "J. N. Israelachvili, Intermolecular and Surface Forces, 3rd ed., Academic Press, 2011.",
    "iso_4287": "ISO 4287:1997, Geometrical Product Specifications (GPS) - Surface texture: Profile method.",
    "iso_25178": "ISO 25178-2:2012, Geometrical product specifications (GPS) - Surface texture: Areal.",
    "fritsch_carlson_1980": (
        "F. N. Fritsch, R. E. Carlson, 'Monotone piecewise cubic interpolation', SIAM J. Numer. Anal. 17 "
        "(1980) 238-246. doi:10.1137/0717021"
    ),
    "jacobs_2017": (
        "T. D. B. Jacobs, T. Junge, L. Pastewka, 'Quantitative characterization of surface topography using "
        "spectral analysis', Surf. Topogr.: Metrol. Prop. 5 (2017) 013001. doi:10.1088/2051-672X/aa51f8"
    ),
    "journel_huijbregts_1978": (
        "A. G. Journel, Ch. J. Huijbregts, Mining Geostatistics, Academic Press, London, 1978 (ch. V: conditional "
        "simulation by kriging)."
    ),
    "teodorescu_2009": (
        "M. Teodorescu, S. Theodossiades, H. Rahnejat, 'Impact dynamics of rough and surface protected MEMS "
        "gears', Tribol. Int. 42 (2009) 197-205. doi:10.1016/j.triboint.2008.04.012"
    ),
    "goryacheva_torskaya_2003": (
        "I. G. Goryacheva, E. V. Torskaya, 'Stress and fracture analysis in periodic contact problem for "
        "coated bodies', Fatigue Fract. Eng. Mater. Struct. 26 (2003) 343-348. doi:10.1046/j.1460-2695.2003.00620.x"
    ),
    "rabotnov_1963": "Yu. N. Rabotnov, 'On the equations of state for creep', Progress in Applied Mechanics, 1963.",
    "srinivasan_1998": (
        "U. Srinivasan, M. R. Houston, R. T. Howe, R. Maboudian, 'Alkyltrichlorosilane-based self-assembled "
        "monolayer films for stiction reduction in silicon micromachines', J. Microelectromech. Syst. 7 (1998) "
        "252-260. doi:10.1109/84.679393"
    ),
    "vollebregt_2014": (
        "E. A. H. Vollebregt, 'A new solver for the elastic normal contact problem using conjugate gradients, "
        "deflation, and an FFT-based preconditioner', J. Comput. Phys. 257 (2014) 333-351. "
        "doi:10.1016/j.jcp.2013.10.005"
    ),
    "ashurst_2001": (
        "W. R. Ashurst, C. Yau, C. Carraro, R. Maboudian, M. T. Dugger, 'Dichlorodimethylsilane as an anti-stiction "
        "monolayer for MEMS: a comparison to the octadecyltrichlorosilane self-assembled monolayer', "
        "J. Microelectromech. Syst. 10 (2001) 41-49. doi:10.1109/84.911090"
    ),
    "srinivasan_report_1998": (
        "U. Srinivasan et al. (Sandia National Laboratories, U. C. Berkeley), 'Lubrication of polysilicon "
        " micromechanisms with self-assembled monolayers', Sandia National Laboratories report, OSTI 671989, "
        "1998. doi:10.2172/671989"
    ),
    "srinivasan_chapter_1998": (
        "U. Srinivasan, M. R. Houston et al., 'Lubrication of polysilicon micromechanisms with "
        "alkylsiloxane self-assembled monolayers: coefficient of static friction measurements', in B. Bhushan (ed.), "
        "Tribology Issues and Opportunities in MEMS, Springer, 1998. doi:10.1007/978-94-011-5050-7_45"
    ),
    "lim_1990": (
        "M. G. Lim, R. M. White et al., 'Polysilicon microstructures to characterize "
        "static friction', Proceedings IEEE Micro Electro Mechanical Systems (MEMS '90), 1990 (IEEE proceedings "
        "record; DOI not found in the searched records)"
    ),
    "gabriel_1990": (
        "K. J. Gabriel, F. Behi, R. Mahadevan, M. Mehregany, 'In situ friction and wear measurements in integrated "
        "polysilicon mechanisms', Sensors and Actuators A 21 (1990); value as cited in the Sandia report "
        "doi:10.2172/671989"
    ),
    "delrio_2007": (
        "F. W. DelRio, M. L. Dunn, L. M. Phinney, C. J. Bourdon, M. P. de Boer, 'Rough surface adhesion in the "
        "presence of capillary condensation', Appl. Phys. Lett. 90 (2007) 163104. doi:10.1063/1.2723658"
    ),
    "fisher_gamble_1981": (
        "L. R. Fisher, R. A. Gamble, J. Middlehurst, 'The Kelvin equation and the capillary condensation of water', "
        "Nature 290 (16 April 1981), measured at p/p0 0.945-0.996 (meniscus radii about 120 to 9 nm) (the "
        "record seen: its first page; DOI not found in the searched records)"
    ),
    "yang_2020": (
        "Q. Yang, P. Z. Sun, L. Fumagalli, Y. V. Stebunov, S. J. Haigh, Z. W. Zhou, I. V. Grigorieva, F. C. Wang, "
        "A. K. Geim, 'Capillary condensation under atomic-scale confinement', Nature 588 (2020) 250-253. "
        "doi:10.1038/s41586-020-2978-1 (arXiv:2009.11238)"
    ),
    "deboer_2007": (
        "M. P. de Boer, 'Capillary adhesion between elastically hard rough surfaces', Exp. Mech. 47 (2007) 171-183. "
        "doi:10.1007/s11340-006-0631-z"
    ),
    "langmuir_2009_rough_capillary": (
        "'Effects of capillary condensation in adhesion between rough surfaces', Langmuir 25 (2009) 11727-11731. "
        "doi:10.1021/la900455k (authors not in the record seen; PubMed 19788224)"
    ),
    "jasper_1972": (
        "J. J. Jasper, 'The surface tension of pure liquid compounds: a compilation of data', J. Phys. Chem. Ref. Data "
        "1 (1972) (National Standard Reference Data System, DTIC ADD095026); linear coefficients as tabulated in the "
        "Jasper-Lange table of the 'chemicals' library (CalebBell/chemicals, chemicals/Interface/Jasper-Lange.tsv)"
    ),
    "chen_2018_water_si": (
        "L. Chen, X. He, H. Liu, L. Qian, S. H. Kim, 'Water adsorption on hydrophilic and hydrophobic surfaces of "
        "silicon', J. Phys. Chem. C 122 (2018) 11385-11391 (ATR-IR isotherms on Si-OH and HF-etched Si-H)"
    ),
    "si_h_contact_angle": (
        "Water contact angle of freshly etched Si-H, 111 +- 1 deg, Table 1 of the article PMC2784167 (Biomaterials; "
        "https://pmc.ncbi.nlm.nih.gov/articles/PMC2784167/)"
    ),
    "vpl_humidity_2014": (
        "'Humidity effects on in situ vapor phase lubrication with n-pentanol', Tribol. Lett. (2014). "
        "doi:10.1007/s11249-014-0345-9 (p/p_sat 0.5 keeps a monolayer of n-pentanol on SiO2)"
    ),
    "butt_kappl_2009": (
        "H.-J. Butt, M. Kappl, 'Normal capillary forces', Adv. Colloid Interface Sci. 146 (2009) 48-60. "
        "doi:10.1016/j.cis.2008.10.002"
    ),
    "asay_kim_2005": (
        "D. B. Asay, S. H. Kim, 'Evolution of the adsorbed water layer structure on silicon oxide at room "
        "temperature', J. Phys. Chem. B 109 (2005) 16760-16763 (its text and DOI not found in the searched records; "
        "the three ice-like layers up to RH 0.3 are its abstract's statement)"
    ),
    "verdaguer_2007": (
        "A. Verdaguer, C. Weis, G. Oncins, G. Ketteler, H. Bluhm, M. Salmeron, 'Growth and structure of water on "
        "SiO2 films on Si investigated by Kelvin probe microscopy and in situ X-ray spectroscopies', Langmuir 23 "
        "(2007) 9699-9703. doi:10.1021/la700893w"
    ),
    "deboer_1998": (
        "M. P. de Boer, P. J. Clews, B. K. Smith, T. A. Michalske, 'Adhesion of polysilicon microbeams in controlled "
        "humidity ambients', MRS Proc. 518 (1998) 131. doi:10.1557/PROC-518-131"
    ),
    "mehregany_2005": (
        "M. Mehregany, S. Rajgopal, A. Izad, 'A unique reliability data point: the start-stop operation of a "
        "polysilicon micromotor at the eight year mark', Proceedings IEEE MEMS 2005, ISBN 0-7803-8994-8 (IEEE "
        "proceedings record; DOI not found in the searched records)"
    ),
    "van_spengen_2010": (
        "W. M. van Spengen, V. Turq, J. W. M. Frenken, 'The description of friction of silicon MEMS with surface "
        "roughness: virtues and limitations of a stochastic Prandtl-Tomlinson model', Beilstein J. Nanotechnol. 1 "
        "(2010) 163-171. doi:10.3762/bjnano.1.20"
    ),
    "static_friction_jmm_1992": (
        "'A study of static friction between silicon and silicon compounds', Journal of Micromechanics and "
        "Microengineering 2(1) (1992) 14-20. doi:10.1088/0960-1317/2/1/004 (millimetre flats at 1e-6 Torr and a "
        "3 mm radius coated bullet on a flat at about 5e-10 Torr; mu 0.2 to 0.7)"
    ),
    "dugger_2007_alcohol": (
        "M. T. Dugger, J. A. Ohlhausen, D. B. Asay, S. H. Kim, 'MEMS lubrication by tribochemical reaction', "
        "Proceedings of the ASME/STLE International Joint Tribology Conference IJTC 2007, pp. 873-875 (2008). "
        "doi:10.1115/IJTC2007-44308"
    ),
    "imece_1999_parallel_plate": (
        "'Stiction study on the microscale via an electrostatically actuated polysilicon parallel plate capacitor' "
        "(title as the abstract states the work; exact title, authors and DOI not read), ASME International Mechanical "
        "Engineering Congress and Exposition IMECE 1999, proceedings abstract IMECE99/16387/275 (ASME digital collection)"
    ),
    "paratte_1991": (
        "L. Paratte, G.-A. Racine, N. F. de Rooij, E. Bornand, 'Design of an integrated electrostatic stepper motor with "
        "axial field', Sensors and Actuators A 25-27 (1991) 597-603 (DOI not found in the searched records; record: "
        "discovery.researcher.life/article/design-of-an-integrated-electrostatic-stepper-motor-with-axial-field)"
    ),
    "sfm_h_silicon_1996": (
        "'Friction forces on hydrogen passivated (110) silicon and silicon dioxide studied by scanning force "
        "microscopy', J. Vac. Sci. Technol. (American Vacuum Society, 1996); record CORE 18252751 from the University of "
        "Basel edoc repository (authors and DOI not read; record: core.ac.uk/display/18252751)"
    ),
    "asay_dugger_kim_vpl": (
        "D. B. Asay, M. T. Dugger, S. H. Kim, 'In-situ vapor-phase lubrication of MEMS', Tribology Letters, issue 1, "
        "pp. 67-74 (Springer, 2007/2008; DOI not read; record: ouci.dntb.gov.ua/works/98VBayv4)"
    ),
    "wang_2015_nanowire_friction": (
        "S. Wang, L. Hou, H. Xie, H. Huang, 'The kinetic friction between a nanowire and a flat substrate measured "
        "using nanomanipulation with optical microscopy', Appl. Phys. Lett. (2015), no. 10. doi:10.1063/1.4930576"
    ),
    "jones_2002_afm_adhesion": (
        "R. Jones, H. M. Pollock, J. A. S. Cleaver, C. S. Hodges, 'Adhesion forces between glass and silicon surfaces "
        "in air studied by AFM: effects of relative humidity, particle size, roughness, and surface treatment', "
        "Langmuir 18 (2002) 8045-8055. doi:10.1021/la0259196"
    ),
    "deng_1995_micromotor_sam": (
        "K. Deng, R. J. Collins, M. Mehregany, C. N. Sukenik, 'Performance impact of monolayer coating of polysilicon "
        "micromotors', J. Electrochem. Soc., pp. 1278-1285. doi:10.1149/1.2044164 (conference version: Proc. IEEE "
        "Micro Electro Mechanical Systems 1995, doi:10.1109/MEMSYS.1995.472568)"
    ),
    "bit_2007_on_chip_tribotester": (
        "'On-chip micro-tribotester and its micro-fabrication', Zhongguo Jixie Gongcheng (China Mechanical Engineering) "
        "18(21) (2007) 2539-2542 (authors and DOI not read; record: pure.bit.edu.cn/en/publications/"
        "on-chip-micro-tribotester-and-its-micro-fabrication)"
    ),
    "zno_nanowire_sio2_sin": (
        "'The kinetic friction of ZnO nanowires on amorphous SiO2 and SiN substrates' (journal, authors and DOI not "
        "read; record: discovery.researcher.life/article/the-kinetic-friction-of-zno-nanowires-on-amorphous-sio2-and-"
        "sin-substrates)"
    ),
    "kennedy_ohagan_2001": (
        "M. C. Kennedy, A. O'Hagan, 'Bayesian calibration of computer models', Journal of the Royal Statistical "
        "Society B 63 (2001) 425-464. doi:10.1111/1467-9868.00294 (the model-discrepancy term)"
    ),
    "kish_1965": "L. Kish, Survey Sampling, Wiley, 1965 (effective sample size of weighted samples, (sum w)^2 / sum w^2).",
    "maboudian_howe_1997": (
        "R. Maboudian, R. T. Howe, 'Critical review: adhesion in surface micromechanical structures', "
        "J. Vac. Sci. Technol. B 15 (1997) 1-20. doi:10.1116/1.589247"
    ),
    "krajcinovic_1996": "D. Krajcinovic, Damage Mechanics, North-Holland (Elsevier), 1996.",
    "hu_1986": (
        "J. Z. Hu, L. D. Merkle, C. S. Menoni, I. L. Spain, 'Crystal data for high-pressure phases of silicon', "
        "Phys. Rev. B 34 (1986) 4679-4684. doi:10.1103/PhysRevB.34.4679"
    ),
    "hamilton_goodman_1966": (
        "G. M. Hamilton, L. E. Goodman, 'The stress field created by a circular sliding contact', "
        "J. Appl. Mech. 33 (1966) 371-376. doi:10.1115/1.3625051"
    ),
    "iso_6336_3": (
        "ISO 6336-3:2019, Calculation of load capacity of spur and helical gears - Part 3: Calculation of tooth "
        "bending strength (method B: 30 deg tangent critical section, form factor Y_F, stress correction factor Y_S)."
    ),
    "iso_53": (
        "ISO 53:1998, Cylindrical gears for general and heavy engineering - Standard basic rack tooth profile "
        "(dedendum 1.25 m, root fillet radius 0.38 m)."
    ),
    "buckingham_1949": "E. Buckingham, Analytical Mechanics of Gears, McGraw-Hill, 1949 (Dover reprint 1988).",
    "deb_2002": (
        "K. Deb, A. Pratap, S. Agarwal, T. Meyarivan, 'A fast and elitist multiobjective genetic algorithm: NSGA-II', "
        "IEEE Trans. Evol. Comput. 6 (2002) 182-197. doi:10.1109/4235.996017"
    ),
    "blank_2020": (
        "J. Blank, K. Deb, 'pymoo: Multi-Objective Optimization in Python', IEEE Access 8 (2020) 89497-89509. "
        "doi:10.1109/ACCESS.2020.2990567"
    ),
    "weibull_1951": (
        "W. Weibull, 'A statistical distribution function of wide applicability', J. Appl. Mech. 18 (1951) "
        "293-297. doi:10.1115/1.4010337"
    ),
    "jadaan_2003": (
        "O. M. Jadaan, N. N. Nemeth, J. Bagdahn, W. N. Sharpe Jr., 'Probabilistic Weibull behavior and mechanical "
        "properties of MEMS brittle materials', J. Mater. Sci. 38 (2003) 4087-4113. doi:10.1023/A:1026317303377"
    ),
    "boyce_2010": (
        "B. L. Boyce, 'A sequential tensile method for rapid characterization of extreme-value behavior in "
        "microfabricated materials', Exp. Mech. 50 (2010) 993-997 (over 1000 polysilicon tensile tests; "
        "threshold strength 1.446 GPa). doi:10.1007/s11340-009-9286-x"
    ),
    "lavan_2001": (
        "D. A. LaVan, T. Tsuchiya, G. Coles, W. G. Knauss, I. Chasiotis, D. Read, 'Cross comparison of direct "
        "strength testing techniques on polysilicon films', in Mechanical Properties of Structural Films, ASTM STP "
        "1413, C. L. Muhlstein and S. B. Brown (eds.), ASTM, West Conshohocken, 2001."
    ),
    "muhlstein_2001": (
        "C. L. Muhlstein, S. B. Brown, R. O. Ritchie, 'High-cycle fatigue of polycrystalline silicon thin films in "
        "laboratory air', Mater. Res. Soc. Symp. Proc. (2001), Materials Science of Microelectromechanical "
        "Systems (MEMS) Devices III: 13 notched 2 um-thick cantilevers cycled to failure in laboratory air "
        "(about 25 degC, 30-50 % RH), lives 5e5 to 1e11 cycles, the stress amplitude at failure falling to about "
        "50 % of the low-cycle strength beyond 1e9 cycles."
    ),
    "alsem_2005": (
        "D. H. Alsem, E. A. Stach, C. L. Muhlstein, R. O. Ritchie, 'Fatigue failure in thin-film polycrystalline "
        "silicon is due to subcritical cracking within the oxide layer', Appl. Phys. Lett. 86 (2005) 041914 (no "
        "fatigue in high vacuum, where oxidation and moisture are suppressed)."
    ),
    "theillet_pierron_2009": (
        "P.-O. Theillet, O. N. Pierron, 'Fatigue rates of monocrystalline silicon thin films in harsh environments: "
        "influence of stress amplitude, relative humidity, and temperature', Appl. Phys. Lett. 94 (2009) 181915. "
        "doi:10.1063/1.3133357"
    ),
    "jaeger_1942": (
        "J. C. Jaeger, 'Moving sources of heat and the temperature at sliding contacts', Proc. R. Soc. N.S.W. 76 "
        "(1942) 203-224."
    ),
    "blok_1937": (
        "H. Blok, 'Theoretical study of temperature rise at surfaces of actual contact under oiliness lubricating "
        "conditions', Proc. General Discussion on Lubrication, IMechE, London, 1937, vol. 2, pp. 222-235."
    ),
    "carslaw_jaeger_1959": "H. S. Carslaw, J. C. Jaeger, Conduction of Heat in Solids, 2nd ed., Oxford, 1959.",
    "mcconnell_2001": (
        "A. D. McConnell, U. Srinivasan, M. Asheghi, K. E. Goodson, 'Thermal conductivity of doped polysilicon "
        "layers', J. Microelectromech. Syst. 10 (2001) 360-369 (LPCVD layers near 1 um thick, B and P doped)."
    ),
    "tai_1987": (
        "Y. C. Tai, C. H. Mastrangelo, R. S. Muller, 'Thermal conductivity of heavily doped LPCVD polysilicon', "
        "IEEE International Electron Devices Meeting, Technical Digest 33 (1987) 278-281 (0.30-0.35 W/(cm K))."
    ),
    "incropera_2007": (
        "F. P. Incropera, D. P. DeWitt, T. L. Bergman, A. S. Lavine, Fundamentals of Heat and Mass Transfer, 6th "
        "ed., Wiley, 2007 (silicon and air property tables A.1, A.4; radiation coefficient Eq. 1.9; thermal contact "
        "resistance Table 3.1; fins of uniform cross-section section 3.6.2, Eqs. 3.69-3.85 and Table 3.4)."
    ),
    "sato_1967": (
        "T. Sato, 'Spectral emissivity of silicon', Jpn. J. Appl. Phys. 6 (1967) 339-347. doi:10.1143/JJAP.6.339 "
        "(heavily doped silicon emits like a grey body of emissivity 0.6-0.7 in the infrared; lightly doped "
        "silicon is partly transparent there)."
    ),
    "timans_1993": (
        "P. J. Timans, 'Emissivity of silicon at elevated temperatures', J. Appl. Phys. 74 (1993) 6353-6364. "
        "doi:10.1063/1.355159 (free-carrier absorption sets the infrared emissivity; thin layers emit less)."
    ),
    "iapws_2014": (
        "IAPWS R1-76(2014), Revised Release on Surface Tension of Ordinary Water Substance, International "
        "Association for the Properties of Water and Steam, 2014."
    ),
    "kluth_1997": (
        "G. J. Kluth, M. M. Sung, R. Maboudian, 'Thermal behavior of alkylsiloxane self-assembled monolayers on the "
        "oxidized Si(100) surface', Langmuir 13 (1997) 3775-3780."
    ),
    "zhuang_2006": (
        "Y. X. Zhuang, O. Hansen, T. Knieling, C. Wang, P. Rombach, W. Lang, W. Benecke, M. Kehlenbeck, J. Koblitz, "
        "'Thermal stability of vapor phase deposited self-assembled monolayers for MEMS anti-stiction', "
        "J. Micromech. Microeng. 16 (2006) 2259-2264. doi:10.1088/0960-1317/16/11/002"
    ),
    "mani_2000": (
        "S. S. Mani et al. (Sandia National Laboratories), 'Effect of W coating on microengine performance', "
        "Proc. IEEE Int. Reliability Physics Symposium (2000) 146-151 (selective CVD of tungsten on polysilicon "
        "MEMS; improved wear resistance of microengines)."
    ),
    "lassner_schubert_1999": (
        "E. Lassner, W.-D. Schubert, Tungsten: Properties, Chemistry, Technology of the Element, Alloys, and "
        "Chemical Compounds, Kluwer Academic/Plenum Publishers, New York, 1999."
    ),
    "wilson_1927": (
        "E. B. Wilson, 'Probable inference, the law of succession, and statistical inference', "
        "J. Am. Stat. Assoc. 22 (1927) 209-212. doi:10.1080/01621459.1927.10502953"
    ),
    "clopper_pearson_1934": (
        "C. J. Clopper, E. S. Pearson, 'The use of confidence or fiducial limits illustrated in the case of the "
        "binomial', Biometrika 26 (1934) 404-413. doi:10.1093/biomet/26.4.404"
    ),
    "sobol_2001": (
        "I. M. Sobol', 'Global sensitivity indices for nonlinear mathematical models and their Monte Carlo "
        "estimates', Math. Comput. Simul. 55 (2001) 271-280. doi:10.1016/S0378-4754(00)00270-6"
    ),
    "saltelli_2010": (
        "A. Saltelli, P. Annoni, I. Azzini, F. Campolongo, M. Ratto, S. Tarantola, 'Variance based sensitivity "
        "analysis of model output. Design and estimator for the total sensitivity index', Comput. Phys. Commun. "
        "181 (2010) 259-270. doi:10.1016/j.cpc.2009.09.018"
    ),
    "herman_usher_2017": (
        "J. Herman, W. Usher, 'SALib: an open-source Python library for sensitivity analysis', J. Open Source "
        "Softw. 2 (2017) 97. doi:10.21105/joss.00097"
    ),
    "spear_hornberger_1980": (
        "R. C. Spear, G. M. Hornberger, 'Eutrophication in Peel Inlet-II. Identification of critical uncertainties "
        "via generalized sensitivity analysis', Water Res. 14 (1980) 43-49. doi:10.1016/0043-1354(80)90040-8"
    ),
    "pianosi_2016": (
        "F. Pianosi, K. Beven, J. Freer, J. W. Hall, J. Rougier, D. B. Stephenson, T. Wagener, 'Sensitivity analysis "
        "of environmental models: a systematic review with practical workflow', Environ. Model. Softw. 79 (2016) "
        "214-232. doi:10.1016/j.envsoft.2016.02.008"
    ),
    "berger_1994": (
        "J. O. Berger, 'An overview of robust Bayesian analysis', Test 3 (1994) 5-124. doi:10.1007/BF02562676"
    ),
    "owen_1998": (
        "A. B. Owen, 'Scrambling Sobol' and Niederreiter-Xing points', J. Complexity 14 (1998) 466-489. "
        "doi:10.1006/jcom.1998.0487"
    ),
    "sharpe_1997": (
        "W. N. Sharpe, B. Yuan, R. Vaidyanathan, R. L. Edwards, 'Measurements of Young's modulus, Poisson's ratio, "
        "and tensile strength of polysilicon', Proc. IEEE MEMS '97 (1997) 424-429. doi:10.1109/MEMSYS.1997.581881"
    ),
    "sharpe_2000": (
        "W. N. Sharpe, K. Jackson, G. Coles, D. A. LaVan, 'Mechanical properties of different polysilicons', "
        "Proc. ASME IMECE 2000, MEMS, 255-259. doi:10.1115/IMECE2000-1100"
    ),
    "yoshizawa_1993": (
        "H. Yoshizawa, Y.-L. Chen, J. Israelachvili, 'Recent advances in molecular level understanding of adhesion, "
        "friction and lubrication', Wear 168 (1993) 161-166. doi:10.1016/0043-1648(93)90212-5"
    ),
    "israelachvili_berman_1999": (
        "J. N. Israelachvili, A. D. Berman, 'Surface forces and microrheology of molecularly thin liquid films', in "
        "B. Bhushan (ed.), Handbook of Micro/Nanotribology, 2nd ed., CRC Press, 1999, ch. 9 (9.8 adhesion "
        "hysteresis; 9.11 the relation between boundary friction and adhesion energy hysteresis)."
    ),
    "kittel_2005": "C. Kittel, Introduction to Solid State Physics, 8th ed., Wiley, 2005 (Table 3.1, cohesive energies).",
    "almqvist_2007": (
        "A. Almqvist, F. Sahlin, R. Larsson, S. Glavatskih, 'On the dry elasto-plastic contact of nominally flat "
        "surfaces', Tribol. Int. 40 (2007) 574-579. doi:10.1016/j.triboint.2005.11.008"
    ),
    "bhushan_li_1997": (
        "B. Bhushan, X. Li, 'Micromechanical and tribological characterization of doped single-crystal silicon and "
        "polysilicon films for microelectromechanical systems devices', J. Mater. Res. 12 (1997) 54-63. "
        "doi:10.1557/JMR.1997.0010"
    ),
    "tabor_1951": "D. Tabor, The Hardness of Metals, Clarendon Press, Oxford, 1951.",
    "li_2011": (
        "Q. Li, T. E. Tullis, D. Goldsby, R. W. Carpick, 'Frictional ageing from interfacial bonding and the origins "
        "of rate and state friction', Nature 480 (2011) 233-236. doi:10.1038/nature10589"
    ),
    "tian_2020": (
        "K. Tian, Z. Li, N. N. Gosvami, D. L. Goldsby, I. Szlufarska, R. W. Carpick, 'Linear aging behavior at short "
        "timescales in nanoscale contacts', Phys. Rev. Lett. 124 (2020) 026801. doi:10.1103/PhysRevLett.124.026801"
    ),
    "prandtl_1928": (
        "L. Prandtl, 'Ein Gedankenmodell zur kinetischen Theorie der festen Koerper', Z. Angew. Math. Mech. 8 (1928) "
        "85-106; G. A. Tomlinson, 'A molecular theory of friction', Phil. Mag. 7 (1929) 905-939; the threshold "
        "eta = 4 pi^2 U0 / (k a^2) as in A. Socoliuc et al., Phys. Rev. Lett. 92 (2004) 134301."
    ),
    "buckingham_1949": (
        "E. Buckingham, Analytical Mechanics of Gears, McGraw-Hill, 1949 (Dover reprint 1988), ch. 18: friction "
        "forces and moments of involute teeth, sliding velocity proportional to the distance from the pitch point."
    ),
    "roundy_cohen_2001": (
        "D. Roundy, M. L. Cohen, 'Ideal strength of diamond, Si, and Ge', Phys. Rev. B 64 (2001) 212103. "
        "doi:10.1103/PhysRevB.64.212103"
    ),
    "de_boer_michalske_1999": (
        "M. P. de Boer, T. A. Michalske, 'Accurate method for determining adhesion of cantilever beams', "
        "J. Appl. Phys. 86 (1999) 817-827. doi:10.1063/1.370809"
    ),
    "vlassak_nix_1992": (
        "J. J. Vlassak, W. D. Nix, 'A new bulge test technique for the determination of Young's modulus and "
        "Poisson's ratio of thin films', J. Mater. Res. 7 (1992) 3242-3249. doi:10.1557/JMR.1992.3242"
    ),
    "bergstrom_1997": (
        "L. Bergstrom, 'Hamaker constants of inorganic materials', Adv. Colloid Interface Sci. 70 (1997) 125-169 "
        "(Lifshitz values of 31 inorganic materials, amorphous silicon nitride among them)."
    ),
}
_used: dict[str, None] = {}
class _Collectors(threading.local):
    """Per thread, ``collectors``: the dicts of the open collect_references() blocks of this thread (None: none yet;
    a class attribute, so that reading it needs no exception: cited functions run ~10^4 times per meshing cycle)."""

    collectors = None


_local = _Collectors()


def cites(*keys: str):
    """Decorator: record ``keys`` in the run's reference list each time the function runs."""
    unknown = [key for key in keys if key not in REFERENCES]
    if unknown:
        raise KeyError(f"unknown reference key(s) {unknown}; add them to memstribo.references.REFERENCES")

    marks = dict.fromkeys(keys)  # update() with it: the keys in order, as assigning them one by one

    def decorate(function):
        @functools.wraps(function)
        def wrapper(*args, **kwargs):
            _used.update(marks)
            collectors = _local.collectors
            if collectors:
                for collected in collectors:
                    collected.update(marks)
            return function(*args, **kwargs)

        wrapper.references = keys
        return wrapper

    return decorate


def used_references() -> list[tuple[str, str]]:
    """The references used since the start (or the last :func:`reset_used_references`)."""
    return [(key, REFERENCES[key]) for key in _used]


def reset_used_references() -> None:
    """Forget the references recorded so far."""
    _used.clear()


def record_references(keys) -> None:
    """Add ``keys`` (reference keys used by work done in another process) to the run's record.

    Raises
    ------
    KeyError
        A key that is not in :data:`REFERENCES`.
    """
    keys = list(keys)
    unknown = [key for key in keys if key not in REFERENCES]
    if unknown:
        raise KeyError(f"unknown reference key(s) {unknown}; add them to memstribo.references.REFERENCES")
    for key in keys:
        _used[key] = None


@contextlib.contextmanager
def collect_references():
    """Collect the reference keys used inside the ``with`` block, in this thread, in order of first use.

    Yields a dict whose keys fill in as cited functions run (the process-wide record of
    :func:`used_references` fills as before). Blocks may nest; each collects what ran inside it::

        with collect_references() as used:
            simulate_mesh(params)
        list(used)   # ['thesis', 'model', ...]
    """
    collected: dict[str, None] = {}
    stack = _local.collectors
    if stack is None:
        stack = _local.collectors = []
    stack.append(collected)
    try:
        yield collected
    finally:
        for i in range(len(stack) - 1, -1, -1):  # by identity: nested blocks may hold equal dicts
            if stack[i] is collected:
                del stack[i]
                break
