//! The rope, two ways (SPEC §3, issue 10): the `thesis` rope (paid out to keep the
//! load 1 m up) must give today's numbers, and the `held` rope (constant hanging
//! length) must make the load a point mass on a pendulum pinned at C: bouncing with
//! the boom at the frequency of the boom loaded by a tip mass, conserving energy,
//! statically indistinguishable from the thesis rope, and riding up with the tip.

use crane_model::data::crane::CraneData;
use crane_model::structure::modal::MeshRefinement;
use crane_model::multibody::ThesisModel;
use crane_model::sim::simulation::{thesis_cases, SimulationOptions};

mod common;
use common::dynamics::model;

/// Every 137th output sample of the twelve thesis cases, computed by the code before
/// the rope modes existed (commit 9c75c73): t, piston force, F_A, tip deflection, swing.
#[rustfmt::skip]
const BASELINE: [(&str, &[[f64; 5]]); 12] = [
("unloaded-30s-linear-up", &[
    [0e0, 1.2799549519834685e5, 1.0066610503395424e5, -1.9964506973542497e-2, 0e0],
    [1.37e0, 1.2993693805210027e5, 1.0013087067411057e5, -2.0594710501152934e-2, 1.7031326018197346e-2],
    [2.74e0, 1.2278029650894176e5, 1.0189128188482224e5, -1.944720199501403e-2, 2.6139104632183052e-2],
    [4.11e0, 1.1760179976422439e5, 1.0325089400853822e5, -1.859298398999498e-2, -4.52413032117116e-3],
    [5.48e0, 1.1341124319315806e5, 1.0440031909656116e5, -1.795815892003601e-2, -2.5791801494980726e-2],
    [6.8500000000000005e0, 1.0975777212490406e5, 1.0544153316824428e5, -1.7462951350580055e-2, -6.899639406577673e-3],
    [8.22e0, 1.0563312686344564e5, 1.0665144349612307e5, -1.680993810645851e-2, 2.2194847107508187e-2],
    [9.59e0, 1.0167033599424323e5, 1.0785695284625822e5, -1.617429194218862e-2, 1.964042329436677e-2],
    [1.096e1, 9.760068543437778e4, 1.0912736079977917e5, -1.548823293191289e-2, -9.147226322105961e-3],
    [1.233e1, 9.34741653991678e4, 1.1043695509120345e5, -1.4778365717130747e-2, -2.3436953841202257e-2],
    [1.3700000000000001e1, 8.943058149405014e4, 1.1173844227282655e5, -1.4095688515762025e-2, -4.821651333565935e-3],
    [1.507e1, 8.532564674537406e4, 1.1307259269564593e5, -1.3396473295044554e-2, 2.051158010348675e-2],
    [1.644e1, 8.106450283249894e4, 1.1446863536311836e5, -1.2648520736998486e-2, 1.931272887046309e-2],
    [1.781e1, 7.663330691931634e4, 1.1592575496424438e5, -1.185247904795237e-2, -5.7263835524790085e-3],
    [1.918e1, 7.210769403203698e4, 1.1741201993658773e5, -1.104336429094227e-2, -2.1937858517456332e-2],
    [2.055e1, 6.75540198265084e4, 1.1890165144249848e5, -1.0251063616455247e-2, -9.370172971017832e-3],
    [2.192e1, 6.290086895307227e4, 1.204129461281505e5, -9.454719934374354e-3, 1.5433764311076015e-2],
    [2.329e1, 5.802200468830976e4, 1.219823310601497e5, -8.61420506771279e-3, 2.171269988889324e-2],
    [2.466e1, 5.286683992579838e4, 1.2362010176212271e5, -7.718601980460737e-3, 2.4010896596711184e-3],
    [2.603e1, 4.749657768330202e4, 1.2529855310522813e5, -6.798044318272972e-3, -1.856477510158938e-2],
    [2.7400000000000002e1, 4.199363407845728e4, 1.2698568729376841e5, -5.889570298047296e-3, -1.6079012691298633e-2],
    [2.877e1, 3.481549276261366e4, 1.2918063477707717e5, -4.878904319755127e-3, 5.558761699187675e-3],
    [3.014e1, 3.51445431352644e4, 1.2905231066132546e5, -4.951965073774192e-3, -5.959075952176152e-3],
]),
("unloaded-30s-linear-down", &[
    [0e0, 3.415621372027248e4, 1.2934358754493488e5, -4.635749745226628e-3, 0e0],
    [1.37e0, 3.186852562161994e4, 1.3006334094947285e5, -4.01364524496999e-3, -2.0447013984392193e-2],
    [2.74e0, 4.160897484296038e4, 1.271010467675559e5, -5.722627830470901e-3, -4.01086221316036e-2],
    [4.11e0, 4.840088072499982e4, 1.2502098541334584e5, -6.98030057313762e-3, -1.0884811204497913e-2],
    [5.48e0, 5.3465237582194495e4, 1.2342974521967985e5, -7.838242736424536e-3, 3.297793665610138e-2],
    [6.8500000000000005e0, 5.8541764879239774e4, 1.2181453082412566e5, -8.707424733476268e-3, 3.806001532525549e-2],
    [8.22e0, 6.3380846861527265e4, 1.2025967631613635e5, -9.529469166886162e-3, -3.006586932099209e-3],
    [9.59e0, 6.789016596061936e4, 1.1879133273312869e5, -1.0283906984543659e-2, -4.0241005893880244e-2],
    [1.096e1, 7.256850389035615e4, 1.1726160728232111e5, -1.1121055583573949e-2, -2.6362577782099716e-2],
    [1.233e1, 7.717390836738044e4, 1.1574724514012692e5, -1.1964229537239551e-2, 2.267673028500128e-2],
    [1.3700000000000001e1, 8.157715485166122e4, 1.1429878109367036e5, -1.2751804479128312e-2, 4.4429797283901395e-2],
    [1.507e1, 8.572670204390977e4, 1.1294285214962333e5, -1.3458754593655834e-2, 8.99367872013146e-3],
    [1.644e1, 8.975027601405072e4, 1.1163655983782391e5, -1.4128367186477118e-2, -3.867203651673368e-2],
    [1.781e1, 9.38729527515884e4, 1.1031069131814054e5, -1.4839795211550202e-2, -3.407340163235539e-2],
    [1.918e1, 9.807218153024341e4, 1.0897641499702082e5, -1.5579748864351754e-2, 1.9116301112123812e-2],
    [2.055e1, 1.0215241209338665e5, 1.0770527689368365e5, -1.6267219941425517e-2, 4.817707092028667e-2],
    [2.192e1, 1.0606506986520629e5, 1.065251671056777e5, -1.687684756424604e-2, 9.621545345770866e-3],
    [2.329e1, 1.0993721529668372e5, 1.0539274833116331e5, -1.7450565916696283e-2, -4.3777004921923934e-2],
    [2.466e1, 1.1399026964899935e5, 1.0424087360996402e5, -1.806560774141876e-2, -3.217320820219238e-2],
    [2.603e1, 1.1818236886548881e5, 1.0308969607157483e5, -1.869741932579425e-2, 3.106543176650134e-2],
    [2.7400000000000002e1, 1.223322858229401e5, 1.0201171366205654e5, -1.9267450442989654e-2, 4.914188578220258e-2],
    [2.877e1, 1.2768596758106683e5, 1.0073770241421713e5, -1.985619414764489e-2, -1.0397099903125984e-2],
    [3.014e1, 1.2692114548530724e5, 1.0095216255605608e5, -1.959759164672331e-2, -3.1144058717995637e-2],
]),
("unloaded-30s-cycloidal-up", &[
    [0e0, 1.2799549519834685e5, 1.0066610503395424e5, -1.9964506973542497e-2, 0e0],
    [1.37e0, 1.2642816112616923e5, 1.0101303210166258e5, -1.9808176620527217e-2, 1.798901783330753e-2],
    [2.74e0, 1.218428601189291e5, 1.0213998127435902e5, -1.919095895709391e-2, 2.7759749871293815e-2],
    [4.11e0, 1.1769494248439347e5, 1.0322591605037177e5, -1.8613339485811512e-2, -4.914710993143556e-3],
    [5.48e0, 1.1359080285819678e5, 1.0435132954629463e5, -1.8010861933392817e-2, -2.7492260120033585e-2],
    [6.8500000000000005e0, 1.0960934409619356e5, 1.0548287033839028e5, -1.742083931293605e-2, -7.332557078698176e-3],
    [8.22e0, 1.0568619963041967e5, 1.0663627665826297e5, -1.6824664595984976e-2, 2.35952447109129e-2],
    [9.59e0, 1.016799640434283e5, 1.0785400748810112e5, -1.6177745026376682e-2, 2.0817729297261778e-2],
    [1.096e1, 9.758151843483024e4, 1.0913299533086449e5, -1.5482524492373632e-2, -9.82195896928717e-3],
    [1.233e1, 9.348029864967277e4, 1.1043540223769147e5, -1.4779634694145241e-2, -2.497606705877997e-2],
    [1.3700000000000001e1, 8.94267716261816e4, 1.1173961878429203e5, -1.4094589993457664e-2, -5.129032099709052e-3],
    [1.507e1, 8.532887827097155e4, 1.1307144428130853e5, -1.339772368735745e-2, 2.1802558939432393e-2],
    [1.644e1, 8.106932277636662e4, 1.1446704010671985e5, -1.265022947385043e-2, 2.0473740118200245e-2],
    [1.781e1, 7.663114545104138e4, 1.1592647357439526e5, -1.1851747401998089e-2, -6.1821210462964515e-3],
    [1.918e1, 7.21030051063176e4, 1.1741358277453335e5, -1.1041584288707024e-2, -2.3390631214728064e-2],
    [2.055e1, 6.755193955805476e4, 1.1890235550815523e5, -1.0250296269833443e-2, -9.976676988989075e-3],
    [2.192e1, 6.290432674290053e4, 1.2041180849556884e5, -9.455991387465671e-3, 1.6405801333550407e-2],
    [2.329e1, 5.802692717787354e4, 1.2198071417493446e5, -8.615990796018947e-3, 2.3039008031334296e-2],
    [2.466e1, 5.286712539550953e4, 1.2362002878304613e5, -7.718709951237156e-3, 2.4635321199344418e-3],
    [2.603e1, 4.749157664049314e4, 1.2530013056979724e5, -6.7962657629997624e-3, -1.9820222983083946e-2],
    [2.7400000000000002e1, 4.19893311759224e4, 1.2698703266052614e5, -5.888057727109867e-3, -1.7130397584993684e-2],
    [2.877e1, 3.417789521250933e4, 1.2935001673724446e5, -4.575647564156328e-3, 6.767755425048039e-3],
    [3.014e1, 3.409516412700199e4, 1.2936230835807216e5, -4.617812735658099e-3, -5.7591814336313e-3],
]),
("unloaded-30s-cycloidal-down", &[
    [0e0, 3.415621372027248e4, 1.2934358754493488e5, -4.635749745226628e-3, 0e0],
    [1.37e0, 3.638582906800432e4, 1.2867508618094516e5, -4.964859776285008e-3, -2.1199577893128874e-2],
    [2.74e0, 4.24872377395473e4, 1.2683635827582321e5, -5.950747588931769e-3, -4.183752668044649e-2],
    [4.11e0, 4.806798850793892e4, 1.2512167501913777e5, -6.896335082517793e-3, -1.1361822284043921e-2],
    [5.48e0, 5.351790436460917e4, 1.2341367952793466e5, -7.850271037905632e-3, 3.432956791880071e-2],
    [6.8500000000000005e0, 5.859776031283856e4, 1.2179748906360868e5, -8.724143618311525e-3, 3.961964490120673e-2],
    [8.22e0, 6.3326489599029264e4, 1.202761143957955e5, -9.514405645610766e-3, -3.1661401188005645e-3],
    [9.59e0, 6.791534334993502e4, 1.1878391503272411e5, -1.0290144622727473e-2, -4.195862418738572e-2],
    [1.096e1, 7.25528804854133e4, 1.1726643732250073e5, -1.1116503397301424e-2, -2.7494797018549733e-2],
    [1.233e1, 7.717819349442986e4, 1.1574586534184348e5, -1.1965633981530938e-2, 2.3598162233763764e-2],
    [1.3700000000000001e1, 8.158497127152552e4, 1.1429617150505724e5, -1.2754555228559655e-2, 4.6260184351126776e-2],
    [1.507e1, 8.572588465354183e4, 1.129430789423478e5, -1.3458654637725536e-2, 9.339466359509663e-3],
    [1.644e1, 8.974636016898861e4, 1.1163793811681283e5, -1.4126776327692015e-2, -4.032168380646195e-2],
    [1.781e1, 9.386878146053375e4, 1.1031212671038885e5, -1.4838219411921247e-2, -3.553027459138902e-2],
    [1.918e1, 9.807429924709682e4, 1.089757064660294e5, -1.5580569731005417e-2, 1.988653275944441e-2],
    [2.055e1, 1.0215710400956267e5, 1.0770357737181512e5, -1.626900401826799e-2, 5.016539843234602e-2],
    [2.192e1, 1.0606627749148247e5, 1.065247965301654e5, -1.6877318794814605e-2, 9.997447373245594e-3],
    [2.329e1, 1.099327994580498e5, 1.0539427011261432e5, -1.744887739277464e-2, -4.5638607892866334e-2],
    [2.466e1, 1.1398741127799558e5, 1.0424189712688369e5, -1.8064512573737212e-2, -3.3553872355963854e-2],
    [2.603e1, 1.1818505763604573e5, 1.0308876459491815e5, -1.8698441377460323e-2, 3.23322539826123e-2],
    [2.7400000000000002e1, 1.2233575733971939e5, 1.0201042996353176e5, -1.926876499522528e-2, 5.1172751060667654e-2],
    [2.877e1, 1.2827395153064278e5, 1.0056427431514711e5, -2.0151817239583193e-2, -1.1613836030787805e-2],
    [3.014e1, 1.2797597807333423e5, 1.006763655074245e5, -1.9954005616035757e-2, -3.1873189180999795e-2],
]),
("3300kg-30s-linear-up", &[
    [0e0, 3.280763534485181e5, 5.953688114200321e4, -9.464255036566784e-2, 0e0],
    [1.37e0, 3.2988878930715815e5, 5.8823928249444616e4, -9.550022130481868e-2, 1.1967636277088634e-2],
    [2.74e0, 3.1395927547039866e5, 6.240398070500121e4, -9.16716260398818e-2, 2.4179214653290204e-2],
    [4.11e0, 3.04588355829971e5, 6.519393814124596e4, -8.93408394617069e-2, 1.0212431810883382e-2],
    [5.48e0, 2.8770700629789144e5, 7.003821976021091e4, -8.416118335827398e-2, -1.3022715281557407e-2],
    [6.8500000000000005e0, 2.741920583297548e5, 7.388341962173274e4, -8.01327734655725e-2, -2.0914973223123745e-2],
    [8.22e0, 2.666234613634452e5, 7.595246495298044e4, -7.822332469808004e-2, -6.587734922044675e-3],
    [9.59e0, 2.606592145009047e5, 7.75625492040131e4, -7.682763401639028e-2, 1.43575215577183e-2],
    [1.096e1, 2.5177376261384957e5, 8.025805209157307e4, -7.424342515845209e-2, 2.124321006130714e-2],
    [1.233e1, 2.3854159492821046e5, 8.452584000158665e4, -6.994985699454763e-2, 8.360881822288002e-3],
    [1.3700000000000001e1, 2.239129527191995e5, 8.934880333677953e4, -6.506657698205419e-2, -1.1186925691834881e-2],
    [1.507e1, 2.1175131079832013e5, 9.336432839150372e4, -6.109719133332719e-2, -1.9136154893839352e-2],
    [1.644e1, 2.0229065631781417e5, 9.633585132492594e4, -5.819491852201397e-2, -8.865445166623909e-3],
    [1.781e1, 1.9576004817208162e5, 9.845929479710647e4, -5.633521728392502e-2, 9.634768530614846e-3],
    [1.918e1, 1.8648425060175962e5, 1.014458335040013e5, -5.347145511471301e-2, 1.980702856567662e-2],
    [2.055e1, 1.7289419713130002e5, 1.0588151337049306e5, -4.904035654884558e-2, 1.316508861059651e-2],
    [2.192e1, 1.5641153887624564e5, 1.1125087252221725e5, -4.359113807310478e-2, -3.9784144157095636e-3],
    [2.329e1, 1.4046889233453074e5, 1.1636407894468852e5, -3.8416734907459775e-2, -1.6732322945650635e-2],
    [2.466e1, 1.2786084941839699e5, 1.2033304684137892e5, -3.4541276410799265e-2, -1.4523263210993065e-2],
    [2.603e1, 1.1815533815250779e5, 1.2331675754273043e5, -3.178357842206627e-2, 3.9904712742067083e-4],
    [2.7400000000000002e1, 1.0805469717839734e5, 1.2635865510693836e5, -2.8960401216495294e-2, 1.5400666740233993e-2],
    [2.877e1, 9.310484372434126e4, 1.3094145566337547e5, -2.4803298933390706e-2, 1.7597463305611738e-2],
    [3.014e1, 8.379115707335391e4, 1.3386698140895367e5, -2.129975958176741e-2, -1.3114990818821504e-2],
]),
("3300kg-30s-linear-down", &[
    [0e0, 8.355932172934375e4, 1.337309618174378e5, -2.1563887875145082e-2, 0e0],
    [1.37e0, 8.449763372312437e4, 1.336340692298273e5, -2.19129729371155e-2, -1.4234335336248849e-2],
    [2.74e0, 9.845893571864023e4, 1.2950740140579802e5, -2.531383905304422e-2, -3.323276603562797e-2],
    [4.11e0, 1.1294470831071828e5, 1.2497897897101704e5, -2.9838829689061375e-2, -2.4205762260470998e-2],
    [5.48e0, 1.3455775803203942e5, 1.1820152579308186e5, -3.688024406128e-2, 5.965016597515138e-3],
    [6.8500000000000005e0, 1.538826353143676e5, 1.119481500188202e5, -4.323196058152238e-2, 3.227925529799003e-2],
    [8.22e0, 1.6645154696334255e5, 1.07910570645854e5, -4.720625174527713e-2, 3.205133465986454e-2],
    [9.59e0, 1.7212741030713991e5, 1.0617114379570486e5, -4.8692519658108016e-2, 4.620908053699857e-3],
    [1.096e1, 1.7638603234182307e5, 1.0484422149880213e5, -4.965443810712891e-2, -2.688406038605562e-2],
    [1.233e1, 1.8627983843818595e5, 1.0164311320713592e5, -5.271752725855134e-2, -3.458610822500896e-2],
    [1.3700000000000001e1, 2.0347118621088483e5, 9.600821281896639e4, -5.855070919857269e-2, -1.0544128507283368e-2],
    [1.507e1, 2.2243840622713705e5, 8.96858776060461e4, -6.508296476282986e-2, 2.4608935737457704e-2],
    [1.644e1, 2.359366665021898e5, 8.520709090433955e4, -6.955424262910928e-2, 3.8587823596910154e-2],
    [1.781e1, 2.421763198322724e5, 8.338593096843676e4, -7.122912671163713e-2, 1.699157500705284e-2],
    [1.918e1, 2.4468015291443662e5, 8.287147962658628e4, -7.142169970710317e-2, -2.1210733059501496e-2],
    [2.055e1, 2.513468496316531e5, 8.093531294586833e4, -7.313847100877564e-2, -3.922285815430304e-2],
    [2.192e1, 2.6675894565672876e5, 7.612750956217996e4, -7.812740151192081e-2, -1.7586116978901334e-2],
    [2.329e1, 2.853498001887933e5, 7.020367411223656e4, -8.424590539974665e-2, 2.4012696308327364e-2],
    [2.466e1, 2.989189443409343e5, 6.610044922791678e4, -8.832778646343956e-2, 4.2903712212137624e-2],
    [2.603e1, 3.052620277781954e5, 6.4845880210723335e4, -8.951184377219575e-2, 1.6772176977907005e-2],
    [2.7400000000000002e1, 3.0782745415558125e5, 6.49690411445921e4, -8.91189856426444e-2, -2.8781849596977604e-2],
    [2.877e1, 3.2082407480243593e5, 6.207149427517313e4, -9.200340338764747e-2, -4.2458728844503524e-2],
    [3.014e1, 3.2963779084991507e5, 5.894859363553114e4, -9.515859789949052e-2, 1.0307254395685472e-2],
]),
("3300kg-30s-cycloidal-up", &[
    [0e0, 3.280763534485181e5, 5.953688114200321e4, -9.464255036566784e-2, 0e0],
    [1.37e0, 3.250566613640494e5, 5.9960009938357965e4, -9.420232737268355e-2, 1.2412717639550763e-2],
    [2.74e0, 3.1634730428124673e5, 6.1844209962560446e4, -9.248802021616953e-2, 2.5104762062380992e-2],
    [4.11e0, 3.0257067905165226e5, 6.563540293630413e4, -8.863366173326317e-2, 1.0592138213369351e-2],
    [5.48e0, 2.875962344597987e5, 7.007734050325466e4, -8.413135346012462e-2, -1.3625129073098874e-2],
    [6.8500000000000005e0, 2.754245633087543e5, 7.363281313542812e4, -8.055966783818991e-2, -2.1819640672154472e-2],
    [8.22e0, 2.6788679439948837e5, 7.567816103242722e4, -7.865793479289306e-2, -6.866760677061601e-3],
    [9.59e0, 2.6167664110341883e5, 7.731929620512389e4, -7.717957630503057e-2, 1.4937007602821017e-2],
    [1.096e1, 2.525900778446001e5, 8.005292870481085e4, -7.452620662645518e-2, 2.2068127305279628e-2],
    [1.233e1, 2.393339651281944e5, 8.434177508882764e4, -7.022052607601355e-2, 8.622413563273756e-3],
    [1.3700000000000001e1, 2.2408217681701216e5, 8.932526362406666e4, -6.512273643758115e-2, -1.1714974833677338e-2],
    [1.507e1, 2.1109974583313087e5, 9.35309285439375e4, -6.087099814259783e-2, -1.9940919974521965e-2],
    [1.644e1, 2.0256508673867804e5, 9.628462699356486e4, -5.8282144563636694e-2, -9.228953245610905e-3],
    [1.781e1, 1.956705208134879e5, 9.846870493087087e4, -5.630905443278043e-2, 1.003947078306866e-2],
    [1.918e1, 1.8662061564032515e5, 1.013937477110107e5, -5.352661773730319e-2, 2.0595099182074028e-2],
    [2.055e1, 1.7317686263581624e5, 1.0580509884301898e5, -4.913607493856761e-2, 1.364221977163238e-2],
    [2.192e1, 1.5648102236800586e5, 1.1124125686500866e5, -4.360917839943093e-2, -4.212681366496884e-3],
    [2.329e1, 1.4027693980897695e5, 1.1642587170557995e5, -3.83481361387459e-2, -1.746389791726699e-2],
    [2.466e1, 1.2766797153786846e5, 1.2039212622884258e5, -3.447389598247115e-2, -1.5128513607060912e-2],
    [2.603e1, 1.1817641771209509e5, 1.2331165670289886e5, -3.1790392578207115e-2, 4.217926123035731e-4],
    [2.7400000000000002e1, 1.0823742802004414e5, 1.263020819777629e5, -2.9023204466996824e-2, 1.6023300851481848e-2],
    [2.877e1, 9.208414655724567e4, 1.3114678602959114e5, -2.4529277482344403e-2, 1.8841389821507848e-2],
    [3.014e1, 7.971019484061484e4, 1.3494615987527155e5, -2.0258964331677873e-2, -1.3424247497129116e-2],
]),
("3300kg-30s-cycloidal-down", &[
    [0e0, 8.355932172934375e4, 1.337309618174378e5, -2.1563887875145082e-2, 0e0],
    [1.37e0, 8.598167246409493e4, 1.330861650644861e5, -2.2076151291262565e-2, -1.4520763904391165e-2],
    [2.74e0, 9.575919229821287e4, 1.3020308978992887e5, -2.457728532955661e-2, -3.4141051364856345e-2],
    [4.11e0, 1.1273997841714667e5, 1.2504360842839848e5, -2.978087666610731e-2, -2.4895483041112998e-2],
    [5.48e0, 1.3476127610833058e5, 1.1815085702447593e5, -3.6934870000437034e-2, 6.107685370187799e-3],
    [6.8500000000000005e0, 1.546227242660249e5, 1.1175652004736659e5, -4.346885509045259e-2, 3.314289756558564e-2],
    [8.22e0, 1.670089379186476e5, 1.0776128673894354e5, -4.7390321764614336e-2, 3.2910594931339965e-2],
    [9.59e0, 1.7232229027795896e5, 1.061251205698903e5, -4.8753864541593264e-2, 4.7249226971812774e-3],
    [1.096e1, 1.762026569005903e5, 1.0490571007909301e5, -4.95846886358868e-2, -2.764735502119109e-2],
    [1.233e1, 1.859397776340194e5, 1.0174477953179936e5, -5.259521160062826e-2, -3.555994611802027e-2],
    [1.3700000000000001e1, 2.034090807960165e5, 9.603114614360617e4, -5.8527808777721894e-2, -1.0855609440087788e-2],
    [1.507e1, 2.2255477272832283e5, 8.964215901069868e4, -6.512804947388037e-2, 2.5269214270331908e-2],
    [1.644e1, 2.3618474122874328e5, 8.512300110808751e4, -6.964712860436274e-2, 3.963354104908823e-2],
    [1.781e1, 2.423180125973943e5, 8.334259196937433e4, -7.128171050031053e-2, 1.7440799958722053e-2],
    [1.918e1, 2.4458363627132503e5, 8.290927199823532e4, -7.13840110042979e-2, -2.1816456046911625e-2],
    [2.055e1, 2.5111474729746536e5, 8.101523306825913e4, -7.304964398796626e-2, -4.032620628456596e-2],
    [2.192e1, 2.6667000264487066e5, 7.616063393839214e4, -7.809326469250344e-2, -1.809310598889846e-2],
    [2.329e1, 2.8549422432601854e5, 7.015545812453408e4, -8.43006481133253e-2, 2.4654567419052587e-2],
    [2.466e1, 2.991195651614744e5, 6.602681102132646e4, -8.840434124266344e-2, 4.406933794512202e-2],
    [2.603e1, 3.0534867108195124e5, 6.4816164150266995e4, -8.95451497039403e-2, 1.7217459560744164e-2],
    [2.7400000000000002e1, 3.076954958588194e5, 6.5017474231980545e4, -8.906884878333542e-2, -2.959544688015492e-2],
    [2.877e1, 3.174966780954023e5, 6.2855731800204725e4, -9.095410239901654e-2, -4.410757784191288e-2],
    [3.014e1, 3.309122693180016e5, 5.8677927854984744e4, -9.569408293190156e-2, 1.0821368773614726e-2],
]),
("3300kg-10s-linear-up", &[
    [0e0, 3.280763534485181e5, 5.953688114200321e4, -9.464255036566784e-2, 0e0],
    [1.37e0, 3.191913979423132e5, 6.062167655485637e4, -9.410684850423173e-2, 5.1342951856067964e-2],
    [2.74e0, 2.7989144337069156e5, 7.050155921274849e4, -8.318996133977401e-2, 7.798845905303198e-2],
    [4.11e0, 2.442795128745813e5, 8.232569263765356e4, -7.214327654243492e-2, 3.406705672231736e-2],
    [5.48e0, 1.9391830825140266e5, 9.868214186416248e4, -5.5211271641934255e-2, -2.882922404150645e-2],
    [6.8500000000000005e0, 1.491889563011796e5, 1.130972696336906e5, -4.0655578563913546e-2, -5.489425273370241e-2],
    [8.22e0, 1.2289360779744273e5, 1.2203203672753152e5, -3.274633811866895e-2, -2.730864275820144e-2],
    [9.59e0, 8.276114123064658e4, 1.343828823476626e5, -2.283387762360917e-2, 1.421406370406375e-2],
]),
("3300kg-10s-linear-down", &[
    [0e0, 8.355932172934375e4, 1.337309618174378e5, -2.1563887875145082e-2, 0e0],
    [1.37e0, 1.0867761103531945e5, 1.2714859000956056e5, -2.7852053849079732e-2, -6.2189541900171674e-2],
    [2.74e0, 1.2523814321834482e5, 1.2083733640021723e5, -3.230677648828343e-2, -1.0745763286001875e-1],
    [4.11e0, 1.859969905504751e5, 1.0231274031368838e5, -5.2348366720403716e-2, -5.4899563983188626e-2],
    [5.48e0, 2.4031363573515014e5, 8.351444080089938e4, -7.126020395738103e-2, 6.0522655551142e-2],
    [6.8500000000000005e0, 2.8633305347424373e5, 6.820102829432984e4, -8.636003271787807e-2, 1.369313003238093e-1],
    [8.22e0, 3.133527809168028e5, 6.1501715471173935e4, -9.333871703129953e-2, 8.654176962289939e-2],
    [9.59e0, 3.2393467543712014e5, 6.124929389966497e4, -9.127865706075013e-2, -5.262252173808002e-2],
]),
("3300kg-10s-cycloidal-up", &[
    [0e0, 3.280763534485181e5, 5.953688114200321e4, -9.464255036566784e-2, 0e0],
    [1.37e0, 3.138655725615977e5, 6.182699693158278e4, -9.241710831479387e-2, 5.2356701300971586e-2],
    [2.74e0, 2.888200324742464e5, 6.844176630637054e4, -8.635482478475782e-2, 7.908983749049892e-2],
    [4.11e0, 2.4698651892500985e5, 8.171961678333604e4, -7.302525132421116e-2, 3.435120420212323e-2],
    [5.48e0, 1.9893562227020264e5, 9.75816511296662e4, -5.687783295900649e-2, -2.968838516075678e-2],
    [6.8500000000000005e0, 1.5459662058629733e5, 1.1188776670380172e5, -4.230043638697936e-2, -5.609006166954833e-2],
    [8.22e0, 1.182973660108981e5, 1.2314124646951165e5, -3.1430781189855164e-2, -2.7749253360584758e-2],
    [9.59e0, 5.507883160144339e4, 1.4231516009296037e5, -1.6784923045139885e-2, 1.8444620044766324e-2],
]),
("3300kg-10s-cycloidal-down", &[
    [0e0, 8.355932172934375e4, 1.337309618174378e5, -2.1563887875145082e-2, 0e0],
    [1.37e0, 9.576178990103242e4, 1.3020961408209245e5, -2.414204604821933e-2, -6.28470793796505e-2],
    [2.74e0, 1.2719053448537084e5, 1.2043427637379947e5, -3.295510682080952e-2, -1.0890373911573459e-1],
    [4.11e0, 1.8051547503039718e5, 1.0355786530185977e5, -5.060241562566171e-2, -5.5608805526257354e-2],
    [5.48e0, 2.4362788364101748e5, 8.274610086501676e4, -7.238860702814556e-2, 6.1089243067827814e-2],
    [6.8500000000000005e0, 2.8678351232389605e5, 6.80551323197576e4, -8.650928975448484e-2, 1.3851064735013874e-1],
    [8.22e0, 3.124784433393343e5, 6.1679269335732344e4, -9.304803495783778e-2, 8.75702303945245e-2],
    [9.59e0, 3.4795442425815726e5, 5.569503611075147e4, -9.758670540197324e-2, -5.696060267606118e-2],
]),
];

#[test]
fn thesis_rope_reproduces_the_numbers_of_the_code_before_rope_modes() {
    let model = model();
    let opts = SimulationOptions::for_type::<f64>();
    for ((name, m), (bname, rows)) in thesis_cases().into_iter().zip(BASELINE) {
        assert_eq!(name, bname);
        let mut got = Vec::new();
        let mut i = 0usize;
        model
            .simulate(&m, &opts, |s| {
                if i % 137 == 0 {
                    got.push([s.t_s, s.reactions.piston_force_n, s.reactions.jack_reaction_n, s.deflection_m[2], s.swing_rad]);
                }
                i += 1;
                true
            })
            .expect("simulation");
        assert_eq!(got.len(), rows.len(), "{name}: sample count");
        let mut worst = 0.0f64;
        for (g, r) in got.iter().zip(rows.iter()) {
            for c in 0..5 {
                // Relative to the value, with a floor of 1e-12 of the column's scale for
                // values that are exactly zero (t = 0, swing at rest).
                let scale = [1.0, 1e5, 1e5, 1e-2, 1e-2][c];
                let rel = (g[c] - r[c]).abs() / r[c].abs().max(1e-3 * scale);
                worst = worst.max(rel);
                assert!(rel <= 1e-9, "{name} t={} column {c}: {} vs {} (rel {rel:e})", r[0], g[c], r[c]);
            }
        }
        println!("{name}: worst relative gap {worst:e}");
    }
}

use crane_model::structure::dense::Square;
use crane_model::structure::eigen::generalized_eigen;
use crane_model::structure::fe::{MAX_DOF, DOF_PER_NODE};
use crane_model::sim::integrator::State;
use crane_model::structure::modal::ModalAnalysis;
use crane_model::multibody::FreeCoordinates;
use crane_model::data::profile::{ActuatorMotion, RampShape};
use crane_model::multibody::rope::{RopeChoice, RopeMode};
use crane_model::sim::simulation::{Maneuver, Program, Segment};
use nalgebra::{SMatrix, SVector};
type M5 = SMatrix<f64, 5, 5>;

/// The held-rope model with the clearance length at `deg` (the load 1 m up there).
fn held_at(model: &ThesisModel<f64>, deg: f64) -> ThesisModel<f64> {
    let l = model.clearance_length_m(deg.to_radians()).expect("length");
    model.with_rope(RopeMode::Held { length_m: l })
}

fn still(model: &ThesisModel<f64>, deg: f64) -> ActuatorMotion<f64> {
    model.actuator_at(deg.to_radians(), 0.0)
}

/// Independent: the boom's finite-element model (12 elements, all 39 dof, the
/// modes' boundary conditions) with the rope and load as a lumped mass at the tip
/// node acting only vertically (a hanging load follows C vertically, and
/// horizontally only at its slow pendulum period): K·x = ω²(M + m·v·vᵀ)·x, v the
/// vertical in the boom frame at node 13. Lowest bending frequency (rad/s).
fn fe_tip_mass_bending_rad_s(crane: &CraneData, deg: f64, tip_mass_kg: f64) -> f64 {
    let an = ModalAnalysis::<f64>::new(crane, MeshRefinement::THESIS).expect("analysis");
    let n = an.mesh.n_dof();
    let mut mass = an.mass;
    let tip = an.mesh.n_nodes() - 1;
    let (u, w) = (DOF_PER_NODE * tip, DOF_PER_NODE * tip + 1);
    let th = deg.to_radians();
    let v = [(u, th.sin()), (w, th.cos())];
    for &(i, vi) in &v {
        for &(j, vj) in &v {
            mass.add(i, j, tip_mass_kg * vi * vj);
        }
    }
    let fixed = [0, 1, DOF_PER_NODE * an.lug_node + 1, DOF_PER_NODE * an.lug_node + 2];
    let free: Vec<usize> = (0..n).filter(|d| !fixed.contains(d)).collect();
    let k: Square<f64, MAX_DOF> = an.stiffness.select(&free).expect("K");
    let m: Square<f64, MAX_DOF> = mass.select(&free).expect("M");
    let pairs = generalized_eigen(&k, &m).expect("eigen");
    // The lowest mode is the first bending of A–C loaded at the tip (the
    // longitudinal and the foot modes are far higher).
    pairs.values[0].sqrt()
}

/// The held model's bounce frequency: the equations of motion linearized at rest
/// (actuator still) about equilibrium, mass matrix of the free coordinates and the
/// stiffness by central differences of the generalized forces; the second-lowest
/// eigenvalue (the lowest is the pendulum swing) (rad/s).
fn held_bounce_rad_s(model: &ThesisModel<f64>, deg: f64, load: f64) -> (f64, f64) {
    let act = still(model, deg);
    let rest = model.equilibrium_state(deg.to_radians(), load).expect("equilibrium");
    let forces = |q: &[f64; 5]| -> SVector<f64, 5> {
        let mut f = rest;
        f.eta.copy_from_slice(&q[..4]);
        f.swing_rad = q[4];
        let cfg = model.kinematics(act, load, &f).expect("kinematics");
        let eq = model.reduced_equations(&cfg);
        SVector::<f64, 5>::from_iterator(eq.force_eta.iter().copied().chain([eq.force_swing]))
    };
    let q0 = [rest.eta[0], rest.eta[1], rest.eta[2], rest.eta[3], rest.swing_rad];
    let mut k = M5::zeros();
    for j in 0..5 {
        let h = if j < 4 { 1e-7 } else { 1e-6 };
        let (mut qp, mut qm) = (q0, q0);
        qp[j] += h;
        qm[j] -= h;
        let col = -(forces(&qp) - forces(&qm)) / (2.0 * h);
        k.set_column(j, &col);
    }
    let k = (k + k.transpose()) * 0.5;
    let cfg = model.kinematics(act, load, &rest).expect("kinematics");
    let blk = model.reduced_equations(&cfg).mass;
    let mut m = M5::zeros();
    for i in 0..4 {
        for j in 0..4 {
            m[(i, j)] = blk.a[(i, j)];
        }
        m[(i, 4)] = blk.b[i];
        m[(4, i)] = blk.b[i];
    }
    m[(4, 4)] = blk.c;
    let l = m.cholesky().expect("M positive definite").l();
    let li = l.try_inverse().expect("L invertible");
    let c = li * k * li.transpose();
    let c = (c + c.transpose()) * 0.5;
    let mut ev: Vec<f64> = c.symmetric_eigen().eigenvalues.iter().copied().collect();
    ev.sort_by(|a, b| a.total_cmp(b));
    (ev[0].sqrt(), ev[1].sqrt())
}

#[test]
fn held_bounce_frequency_at_40_deg_matches_the_boom_with_a_tip_mass() {
    let crane = CraneData::coles_mobile_930();
    let base = model();
    let held = held_at(&base, 40.0);
    let l = held.hanging_length_m(0.0).expect("length");
    for load in [0.0, 3300.0, 7290.0] {
        let (swing, bounce) = held_bounce_rad_s(&held, 40.0, load);
        let tip_mass = load + base.rope_kg_per_m * l;
        let fe = fe_tip_mass_bending_rad_s(&crane, 40.0, tip_mass);
        let gap = bounce / fe - 1.0;
        println!(
            "W = {load} kg, L = {l:.3} m: held model bounce {:.4} Hz, FE boom + {tip_mass:.1} kg tip mass {:.4} Hz (gap {:+.2} %); swing {:.3} s (2π√(L/g) = {:.3} s)",
            bounce / (2.0 * std::f64::consts::PI),
            fe / (2.0 * std::f64::consts::PI),
            100.0 * gap,
            2.0 * std::f64::consts::PI / swing,
            2.0 * std::f64::consts::PI * (l / base.gravity_m_s2).sqrt()
        );
        assert!(gap.abs() < 0.03, "W = {load}: bounce {bounce} vs FE {fe}");
    }
}

/// Total energy with the actuator locked: kinetic ½ẏᵀMẏ over all coordinates,
/// gravity potential of the boom's deformable part and of body 5, strain ½Σω²η²
/// (as in `solver_checks.rs`; the rigid bodies 1–4 do not move).
fn energy(model: &ThesisModel<f64>, act: ActuatorMotion<f64>, load: f64, free: &FreeCoordinates<f64, 4>) -> f64 {
    let cfg = model.kinematics(act, load, free).expect("kinematics");
    let sys = model.full_system(&cfg).expect("full system");
    let mut kinetic = 0.0;
    for i in 0..sys.n {
        for j in 0..sys.n {
            kinetic += 0.5 * sys.velocity[i] * sys.mass.get(i, j) * sys.velocity[j];
        }
    }
    let g = model.gravity_m_s2;
    let m = &model.modes;
    let (s1, c1) = (cfg.mech.boom.angle.sin(), cfg.mech.boom.angle.cos());
    let (mut sx, mut sy, mut strain) = (m.first_moment_rest[0], m.first_moment_rest[1], 0.0);
    for k in 0..4 {
        sx += m.first_moment_modes[0][k] * free.eta[k];
        sy += m.first_moment_modes[1][k] * free.eta[k];
        strain += 0.5 * m.omega_rad_s[k] * m.omega_rad_s[k] * free.eta[k] * free.eta[k];
    }
    let p = &cfg.pendulum;
    kinetic + g * (s1 * sx + c1 * sy) + g * (p.mass_kg * cfg.tip_position.y + p.first_moment_kg_m * free.swing_rad.sin()) + strain
}

#[test]
fn held_energy_is_conserved_at_the_production_step_with_damping_off_and_actuator_still() {
    let mut base = model();
    base.modes.damping = [0.0; 4];
    let held = held_at(&base, 40.0);
    let (deg, load) = (40.0, 3300.0);
    let act = still(&held, deg);
    let rest = held.equilibrium_state(deg.to_radians(), load).expect("equilibrium");
    let e_rest = energy(&held, act, load, &rest);
    // Off equilibrium: the boom bent as it would be under twice the load (a bounce,
    // released from there) and the load swung 0.05 rad.
    let mut free = held.equilibrium_state(deg.to_radians(), 2.0 * load).expect("bent");
    free.swing_rad += 0.05;
    let tip_of = |f: &FreeCoordinates<f64, 4>| -> f64 { (0..4).map(|k| held.modes.tip_modes[1][k] * (f.eta[k] - rest.eta[k])).sum() };
    let released = tip_of(&free).abs();
    let e0 = energy(&held, act, load, &free);
    let oscillation = e0 - e_rest;
    assert!(oscillation > 0.0);
    let opts = SimulationOptions::for_type::<f64>();
    let h = opts.step_s;
    assert_eq!(h, 2e-3, "production step");
    let (mut st, _) = State::new(&held, 0.0, act, load, free).expect("state");
    let (mut worst, mut max_tip, mut max_swing) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..(10.0 / h).round() as usize {
        st.step(&held, h, act, opts.tolerance).expect("step");
        let e = energy(&held, act, load, &st.free);
        worst = worst.max((e - e0).abs());
        max_tip = max_tip.max(tip_of(&st.free).abs());
        max_swing = max_swing.max((st.free.swing_rad - rest.swing_rad).abs());
    }
    let rel = worst / oscillation;
    println!("released {released:.4} m off equilibrium at the tip; oscillation energy {oscillation:.2} J, max |E − E0| over 10 s at h = 2 ms: {worst:.3e} J ({rel:.2e} relative); bounce ≤ {max_tip:.4} m, swing ≤ {max_swing:.4} rad");
    // The motion really is the disturbed one (no numerical damping of bounce or swing).
    assert!(max_tip > 0.95 * released && released > 0.03 && max_swing > 0.049);
    assert!(rel < 1e-4, "energy drift {rel:e}");
}

#[test]
fn at_rest_both_rope_modes_give_the_same_piston_force_and_jack_reaction() {
    let base = model();
    for deg in [20.0, 40.0, 60.0, 80.0] {
        let held = held_at(&base, deg);
        for load in [0.0, 3300.0] {
            let a = base.reactions_at_rest(f64::to_radians(deg), load).expect("thesis");
            let b = held.reactions_at_rest(f64::to_radians(deg), load).expect("held");
            let df = (a.piston_force_n - b.piston_force_n).abs() / a.piston_force_n.abs();
            let dj = (a.jack_reaction_n - b.jack_reaction_n).abs() / a.jack_reaction_n.abs();
            println!("{deg}° {load} kg: F {:.3} / {:.3} N, F_A {:.3} / {:.3} N", a.piston_force_n, b.piston_force_n, a.jack_reaction_n, b.jack_reaction_n);
            assert!(df <= 1e-6 && dj <= 1e-6, "{deg}° {load} kg: rel gaps {df:e} {dj:e}");
        }
    }
}

#[test]
fn held_rope_tension_in_the_start_ramp_is_the_load_riding_up_with_the_tip() {
    let base = model();
    let (load, deg0) = (3300.0, 40.0);
    let mut m = Maneuver::thesis(load, 10.0, RampShape::Linear, crane_model::sim::simulation::Direction::Up).expect("maneuver");
    m.rope = RopeChoice::Held { length_m: None };
    let program = m.program().expect("program");
    let held = held_at(&base, deg0);
    let sched = held.schedule(&program).expect("schedule");
    let l = held.hanging_length_m(0.0).expect("length");
    let m5 = load + base.rope_kg_per_m * l;
    let g = base.gravity_m_s2;
    let lc = base.modes.length_m;
    let mut opts = SimulationOptions::for_type::<f64>();
    opts.output_every = 1;
    let (mut sum_t, mut sum_k, mut n, mut worst) = (0.0, 0.0, 0usize, 0.0f64);
    let mut static_t = 0.0;
    base.simulate(&m, &opts, |s| {
        if s.t_s == 0.0 {
            static_t = s.rope_tension_n;
        }
        // Inside the start ramp (0, t1 = 1 s), away from its edges.
        if s.t_s > 0.1 && s.t_s < 0.95 {
            let boom = held.geometry.motion(sched.actuator_at(s.t_s)).expect("motion").boom;
            let (c, sn) = (boom.axis.x, boom.axis.y);
            let y_acc = lc * (c * boom.angular_acceleration - sn * boom.angular_velocity * boom.angular_velocity);
            let kin = m5 * (g + y_acc);
            sum_t += s.rope_tension_n;
            sum_k += kin;
            n += 1;
            worst = worst.max((s.rope_tension_n - kin).abs() / kin);
        }
        s.t_s < 1.0
    })
    .expect("simulation");
    let (mean_t, mean_k) = (sum_t / n as f64, sum_k / n as f64);
    let extra = mean_t / static_t - 1.0;
    println!(
        "start ramp: mean rope force {mean_t:.0} N vs W·(g + ÿ_tip) {mean_k:.0} N (gap {:+.2} %), static {static_t:.0} N, extra {:.1} %, worst instant gap {:.1} % (the bounce)",
        100.0 * (mean_t / mean_k - 1.0),
        100.0 * extra,
        100.0 * worst
    );
    assert!((static_t / (m5 * g) - 1.0).abs() < 1e-3, "static rope force {static_t} vs {}", m5 * g);
    assert!((mean_t / mean_k - 1.0).abs() < 0.05);
    // The load really rides up: several percent of extra rope force.
    assert!(extra > 0.05, "extra rope force {extra}");
}

#[test]
fn lift_off_takes_the_load_up_and_the_crane_settles_at_its_static_state() {
    let base = model();
    let (deg, load) = (50.0, 3300.0);
    for rope in [RopeChoice::Thesis, RopeChoice::Held { length_m: Some(8.0) }] {
        let mut p = Program::new(deg, 0.0, rope).expect("program");
        p.push(Segment::Hold { duration_s: 0.5 }).expect("hold");
        p.push(Segment::LiftOff { duration_s: 2.0, load_kg: load }).expect("lift");
        p.push(Segment::Hold { duration_s: 6.0 }).expect("hold");
        let mut opts = SimulationOptions::for_type::<f64>();
        opts.output_every = 5;
        let mut rows = Vec::new();
        base.simulate_program(&p, &opts, |s| {
            rows.push((s.t_s, s.hook_load_kg, s.reactions.piston_force_n, s.rope_tension_n));
            true
        })
        .expect("simulation");
        let at = |t: f64| rows.iter().min_by(|a, b| (a.0 - t).abs().total_cmp(&(b.0 - t).abs())).copied().expect("row");
        let model = match rope {
            RopeChoice::Held { length_m: Some(l) } => base.with_rope(RopeMode::Held { length_m: l }),
            _ => base,
        };
        let empty = model.reactions_at_rest(deg.to_radians(), 0.0).expect("rest").piston_force_n;
        let full = model.reactions_at_rest(deg.to_radians(), load).expect("rest").piston_force_n;
        // Before the lift the hook is empty; half-way it carries half; after, all.
        assert!((at(0.4).2 / empty - 1.0).abs() < 1e-6);
        assert!((at(1.5).1 - load / 2.0).abs() < 1e-6);
        let end = at(8.5);
        assert_eq!(end.1, load);
        // The ramp's end leaves a bounce; its mean over the last 3 s is the static state.
        let tail: Vec<f64> = rows.iter().filter(|r| r.0 >= 5.5).map(|r| r.2).collect();
        let mean = tail.iter().sum::<f64>() / tail.len() as f64;
        println!("{rope:?}: piston force empty {empty:.0} N, end {:.0} N, mean of the last 3 s {mean:.0} N (static {full:.0} N)", end.2);
        assert!((mean / full - 1.0).abs() < 0.01, "{mean} vs {full}");
        assert!(rows.iter().all(|r| r.1 >= 0.0 && r.1 <= load));
    }
}

#[test]
fn piston_force_by_inverse_dynamics_along_the_actuator_equals_the_multiplier() {
    let base = model();
    let mut worst = 0.0f64;
    for (rope, case) in [(RopeChoice::Thesis, 8usize), (RopeChoice::Held { length_m: None }, 8), (RopeChoice::Thesis, 3), (RopeChoice::Held { length_m: Some(5.0) }, 11)] {
        let (_, mut m) = thesis_cases()[case];
        m.rope = rope;
        let program = m.program().expect("program");
        let start = m.angles_deg().0.to_radians();
        let model = base.with_rope(base.rope_for(rope, start).expect("rope"));
        let sched = model.schedule(&program).expect("schedule");
        let mut opts = SimulationOptions::for_type::<f64>();
        opts.output_every = 7;
        model
            .simulate_program(&program, &opts, |s| {
                // Re-evaluate this sample's state off the run: its free coordinates are not in
                // the sample, so check at a state built from the sample's time and a swinging load.
                let t = s.t_s;
                let act = sched.actuator_at(t);
                let mut free = model.equilibrium_state(s.boom_angle_rad, sched.load_at(t)).expect("eq");
                free.swing_rad += 0.03 * (t * 1.3).sin();
                free.swing_rate = 0.02 * (t * 0.7).cos();
                for k in 0..4 {
                    free.eta_rate[k] = 1e-3 * ((k + 1) as f64 * t).sin();
                }
                let ev = model.evaluate(act, sched.load_at(t), &free).expect("evaluate");
                let (_, lambda) = model.multipliers(&ev).expect("multipliers");
                let by_multiplier = model.reactions(&lambda).piston_force_n;
                let by_power = model.piston_force_along_actuator_n(&ev).expect("power");
                let rel = (by_power - by_multiplier).abs() / by_multiplier.abs();
                worst = worst.max(rel);
                assert!(rel < 1e-9, "t = {t}: {by_power} vs {by_multiplier}");
                true
            })
            .expect("simulation");
    }
    println!("worst relative gap between the power balance and the multiplier: {worst:e}");
}

/// Piston force after the first ramp: half peak-to-peak about a quadratic trend over
/// [t1, t1 + 3 s], and the dominant frequency (DFT peak over 0.5–10 Hz).
fn oscillation_after_ramp(rows: &[(f64, f64, f64)], t1: f64) -> (f64, f64) {
    let w: Vec<(f64, f64)> = rows.iter().filter(|r| r.0 >= t1 && r.0 <= t1 + 3.0).map(|r| (r.0 - t1, r.2)).collect();
    // Quadratic least squares (normal equations, 3×3).
    let mut a = nalgebra::Matrix3::<f64>::zeros();
    let mut b = nalgebra::Vector3::<f64>::zeros();
    for &(t, f) in &w {
        let x = nalgebra::Vector3::new(1.0, t, t * t);
        a += x * x.transpose();
        b += x * f;
    }
    let c = a.lu().solve(&b).expect("fit");
    let res: Vec<(f64, f64)> = w.iter().map(|&(t, f)| (t, f - (c[0] + c[1] * t + c[2] * t * t))).collect();
    let (lo, hi) = res.iter().fold((f64::MAX, f64::MIN), |(lo, hi), r| (lo.min(r.1), hi.max(r.1)));
    let mut best = (0.0, 0.0);
    for i in 50..=1000 {
        let f = i as f64 / 100.0;
        let (re, im) = res.iter().fold((0.0, 0.0), |(re, im), &(t, v)| (re + v * (2.0 * std::f64::consts::PI * f * t).cos(), im + v * (2.0 * std::f64::consts::PI * f * t).sin()));
        if re.hypot(im) > best.1 {
            best = (f, re.hypot(im));
        }
    }
    ((hi - lo) / 2.0, best.0)
}

#[test]
fn held_rope_thesis_maneuvers_oscillate_more_at_the_loaded_bounce_frequency() {
    let base = model();
    let opts = SimulationOptions { output_every: 1, ..SimulationOptions::for_type::<f64>() };
    let l = base.clearance_length_m(40f64.to_radians()).expect("length");
    for name in ["3300kg-30s-cycloidal-up", "3300kg-10s-linear-up"] {
        let (_, m) = thesis_cases().into_iter().find(|(n, _)| *n == name).expect("case");
        let mut out = Vec::new();
        for rope in [RopeChoice::Thesis, RopeChoice::Held { length_m: Some(l) }] {
            let mut rows = Vec::new();
            base.simulate(&Maneuver { rope, ..m }, &opts, |s| {
                rows.push((s.t_s, s.boom_angle_rad.to_degrees(), s.reactions.piston_force_n));
                true
            })
            .expect("simulation");
            let at = |deg: f64| {
                let i = rows.iter().position(|r| r.1 >= deg).expect("angle reached");
                let (a, b) = (rows[i - 1], rows[i]);
                a.2 + (deg - a.1) / (b.1 - a.1) * (b.2 - a.2)
            };
            let (half_pp, hz) = oscillation_after_ramp(&rows, m.t1_s);
            println!(
                "{name} {:>6}: F(45°) {:.2} kN, F(60°) {:.2} kN, F(75°) {:.2} kN; after the first ramp: half peak-to-peak {:.2} kN, {hz:.2} Hz (period {:.3} s)",
                if rope == RopeChoice::Thesis { "thesis" } else { "held" },
                at(45.0) / 1e3,
                at(60.0) / 1e3,
                at(75.0) / 1e3,
                half_pp / 1e3,
                1.0 / hz
            );
            out.push((half_pp, hz));
        }
        // The held load joins the bounce: more than twice the thesis rope's oscillation,
        // at the loaded boom's bounce frequency (1.85 Hz at 40° with 3.3 t, rising as the
        // radius shrinks) in both modes.
        assert!(out[1].0 > 2.0 * out[0].0, "{name}: held {} vs thesis {}", out[1].0, out[0].0);
        for (_, hz) in &out {
            assert!((1.7..2.2).contains(hz), "{name}: {hz} Hz");
        }
    }
}

/// A hoist with the boom still: the winch takes 5 t hanging 10 m at 50°
/// 4 m up in 10 s and lets it 4 m down again, each with linear ramps of 2 s
/// (v = 4 / (10 − 2) = 0.5 m/s, a = v / 2 s = 0.25 m/s²). Newton's second law
/// on the load: the rope pulls (W + rope)·(g + a) while the load speeds up
/// upward or slows down from going down, (W + rope)·(g − a) the other two
/// ramps, and its weight at constant speed. Checked over each window, mean
/// of the rope tension against the tension at rest before the hoist scaled
/// by (g ± a)/g, and the piston force against the model's static force of
/// the load W·(g ± a)/g, a second way the cylinder must see the same pull.
/// The ramps' steps of acceleration set the load bouncing on the boom: the
/// windows skip their first half second, where the bounce is largest.
#[test]
fn a_hoist_loads_the_rope_by_the_loads_acceleration() {
    let base = model();
    let (deg, load, length) = (50.0, 5000.0, 10.0);
    let rope = RopeChoice::Held { length_m: Some(length) };
    let mut p = Program::new(deg, load, rope).expect("program");
    p.push(Segment::Hold { duration_s: 1.0 }).expect("hold");
    p.push(Segment::Hoist { by_m: 4.0, duration_s: 10.0, ramp_s: 2.0, shape: RampShape::Linear }).expect("hoist up");
    p.push(Segment::Hold { duration_s: 4.0 }).expect("hold");
    p.push(Segment::Hoist { by_m: -4.0, duration_s: 10.0, ramp_s: 2.0, shape: RampShape::Linear }).expect("hoist down");
    p.push(Segment::Hold { duration_s: 4.0 }).expect("hold");
    let mut rows = Vec::new();
    base.simulate_program(&p, &SimulationOptions::for_type::<f64>(), |s| {
        rows.push((s.t_s, s.rope_tension_n, s.reactions.piston_force_n, s.swing_rad));
        true
    })
    .expect("simulation");
    let mean = |from: f64, to: f64, k: usize| {
        let v: Vec<f64> = rows.iter().filter(|r| r.0 >= from && r.0 < to).map(|r| [r.1, r.2][k]).collect();
        v.iter().sum::<f64>() / v.len() as f64
    };
    let g = 9.80665;
    let a = 0.25;
    let held = base.with_rope(RopeMode::Held { length_m: length });
    let static_force = |w: f64| held.reactions_at_rest(deg.to_radians(), w).expect("rest").piston_force_n;
    let rest_tension = mean(0.0, 1.0, 0);
    assert!((rest_tension / (load * g) - 1.0).abs() < 0.01, "tension at rest {rest_tension:.0} N");
    // (window start, end, the load's upward acceleration)
    let windows = [
        (1.5, 3.0, a),
        (4.0, 9.0, 0.0),
        (9.5, 11.0, -a),
        (12.0, 15.0, 0.0),
        (15.5, 17.0, -a),
        (18.0, 23.0, 0.0),
        (23.5, 25.0, a),
        (26.0, 29.0, 0.0),
    ];
    for (from, to, acc) in windows {
        let tension = mean(from, to, 0);
        let want_tension = rest_tension * (g + acc) / g;
        let force = mean(from, to, 1);
        let want_force = static_force(load * (g + acc) / g);
        println!("{from:4.1}-{to:4.1} s, a = {acc:+.2} m/s²: rope {tension:.0} N (Newton {want_tension:.0} N), piston {force:.0} N (static {want_force:.0} N)");
        assert!((tension / want_tension - 1.0).abs() < 0.005, "{from}-{to} s: rope tension {tension:.0} N, Newton's law {want_tension:.0} N");
        assert!((force / want_force - 1.0).abs() < 0.005, "{from}-{to} s: piston force {force:.0} N, static {want_force:.0} N");
    }
    // A load hoisted straight up does not swing.
    let swing = rows.iter().map(|r| r.3.abs()).fold(0.0, f64::max).to_degrees();
    assert!(swing < 0.5, "swing {swing:.2}°");
}

/// A hoist is refused on the thesis's rope, and where it would leave less
/// than a metre of rope or more than the tip's height hanging.
#[test]
fn a_hoist_needs_a_held_rope_and_a_length_that_fits() {
    let hoist = |by_m: f64| Segment::Hoist { by_m, duration_s: 10.0, ramp_s: 1.0, shape: RampShape::Linear };
    let mut thesis = Program::new(50.0, 3000.0, RopeChoice::Thesis).expect("program");
    assert!(thesis.push(hoist(2.0)).is_err());
    let base = model();
    for (by_m, fits) in [(4.0, true), (9.5, false), (-3.0, true), (-30.0, false)] {
        let mut p = Program::new(50.0, 3000.0, RopeChoice::Held { length_m: Some(10.0) }).expect("program");
        p.push(hoist(by_m)).expect("segment");
        let model = base.with_rope(RopeMode::Held { length_m: 10.0 });
        assert_eq!(model.schedule(&p).is_ok(), fits, "hoist by {by_m} m from 10 m");
    }
}
