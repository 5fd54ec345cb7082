<?xml version="1.0" encoding="UTF-8" standalone="yes"?>
<CityModel gml:id="cm1" xmlns:app="http://www.opengis.net/citygml/appearance/3.0" xmlns:brid="http://www.opengis.net/citygml/bridge/3.0" xmlns:bldg="http://www.opengis.net/citygml/building/3.0" xmlns:frn="http://www.opengis.net/citygml/cityfurniture/3.0" xmlns:grp="http://www.opengis.net/citygml/cityobjectgroup/3.0" xmlns:con="http://www.opengis.net/citygml/construction/3.0" xmlns:pcl="http://www.opengis.net/citygml/pointcloud/3.0" xmlns:core="http://www.opengis.net/citygml/3.0" xmlns:dyn="http://www.opengis.net/citygml/dynamizer/3.0" xmlns:gen="http://www.opengis.net/citygml/generics/3.0" xmlns:luse="http://www.opengis.net/citygml/landuse/3.0" xmlns:dem="http://www.opengis.net/citygml/relief/3.0" xmlns:tran="http://www.opengis.net/citygml/transportation/3.0" xmlns:tun="http://www.opengis.net/citygml/tunnel/3.0" xmlns:veg="http://www.opengis.net/citygml/vegetation/3.0" xmlns:vers="http://www.opengis.net/citygml/versioning/3.0" xmlns:wtr="http://www.opengis.net/citygml/waterbody/3.0" xmlns:tsml="http://www.opengis.net/tsml/1.0" xmlns:sos="http://www.opengis.net/sos/2.0" xmlns:xAL="urn:oasis:names:tc:ciq:xsdschema:xAL:2.0" xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xmlns:gml="http://www.opengis.net/gml/3.2" xmlns:ade="http://www.3dcitydb.org/citygml-ade/3.0/citygml/1.0" xmlns="http://www.opengis.net/citygml/3.0" xsi:schemaLocation="http://www.opengis.net/citygml/appearance/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/appearance.xsd http://www.opengis.net/citygml/bridge/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/bridge.xsd http://www.opengis.net/citygml/building/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/building.xsd http://www.opengis.net/citygml/cityfurniture/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/cityFurniture.xsd http://www.opengis.net/citygml/cityobjectgroup/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/cityObjectGroup.xsd http://www.opengis.net/citygml/construction/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/construction.xsd http://www.opengis.net/citygml/pointcloud/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/pointCloud.xsd http://www.opengis.net/citygml/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/cityGMLBase.xsd http://www.opengis.net/citygml/dynamizer/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/dynamizer.xsd http://www.opengis.net/citygml/generics/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/generics.xsd http://www.opengis.net/citygml/landuse/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/landUse.xsd http://www.opengis.net/citygml/relief/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/relief.xsd http://www.opengis.net/citygml/transportation/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/transportation.xsd http://www.opengis.net/citygml/tunnel/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/tunnel.xsd http://www.opengis.net/citygml/vegetation/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/vegetation.xsd http://www.opengis.net/citygml/versioning/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/versioning.xsd http://www.opengis.net/citygml/waterbody/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/waterBody.xsd http://www.opengis.net/tsml/1.0 http://schemas.opengis.net/tsml/1.0/timeseriesML.xsd http://www.opengis.net/sos/2.0 http://schemas.opengis.net/sos/2.0/sosGetObservation.xsd urn:oasis:names:tc:ciq:xsdschema:xAL:2.0 http://schemas.opengis.net/citygml/xAL/xAL.xsd">
    <gml:name>LoD2_4490_5322_1_BY</gml:name>
    <gml:boundedBy>
        <gml:Envelope srsName="urn:adv:crs:DE_DHDN_3GK4*DE_DHHN92_NH" srsDimension="3">
            <gml:lowerCorner>4490655.500 5322005.280 548.470</gml:lowerCorner>
            <gml:upperCorner>4490671.290 5322017.800 557.020</gml:upperCorner>
        </gml:Envelope>
    </gml:boundedBy>
    <cityObjectMember>
        <bldg:Building gml:id="DEBY_LOD2_5744682">
            <gml:name>DEBY_LOD2_5744682</gml:name>
            <creationDate>2014-10-08T00:00:00</creationDate>
            <lod2Solid>
                <gml:Solid gml:id="DEBY_LOD2_5744682_sl_N65569">
                    <gml:exterior>
                        <gml:Shell>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_1e36b54e-2518-4afe-a2b4-a59ddff93581_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_26de5877-57e7-429d-9b9a-274b8ed6aac5_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_314d7d2e-1551-4946-80a4-12e463d59de5_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_392cb098-6e22-4334-9853-1e8225966156_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_44e7c68d-da01-4f80-b1a4-9bbde8305c77_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_58e93bde-fd64-4fec-9626-5824c2e94f0e_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_5e13d1c8-7fb5-479f-9794-7b9e1f89ca1e_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_6a1b5359-d4e4-4d80-aeb8-ad63625a56dc_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_80ce6c2a-8724-4a2a-89e4-881da9530ecc_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_887068cb-0fcb-45f3-b436-d1a1bdef047f_poly"/>
                            <gml:surfaceMember xlink:href="#DEBY_LOD2_5744682_dd1b367c-c6d8-4eb2-abe6-0accb0fa91b8_poly"/>
                        </gml:Shell>
                    </gml:exterior>
                </gml:Solid>
            </lod2Solid>
            <boundary>
                <con:RoofSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_5e13d1c8-7fb5-479f-9794-7b9e1f89ca1e_msl_N65598">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_5e13d1c8-7fb5-479f-9794-7b9e1f89ca1e_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490663.450 5322007.590 555.191 4490663.250 5322006.210 554.643 4490666.840 5322005.700 554.642 4490669.800 5322005.280 554.641 4490670.002 5322006.703 555.206 4490670.649 5322011.271 557.020 4490656.141 5322013.320 557.020 4490655.500 5322008.750 555.206 4490663.450 5322007.590 555.191</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:RoofSurface>
            </boundary>
            <boundary>
                <con:WallSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_314d7d2e-1551-4946-80a4-12e463d59de5_msl_N65610">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_314d7d2e-1551-4946-80a4-12e463d59de5_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490664.850 5322016.660 548.470 4490664.850 5322016.660 555.241 4490664.850 5322016.700 555.226 4490664.850 5322016.700 548.470 4490664.850 5322016.660 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:WallSurface>
            </boundary>
            <boundary>
                <con:WallSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_6a1b5359-d4e4-4d80-aeb8-ad63625a56dc_msl_N65622">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_6a1b5359-d4e4-4d80-aeb8-ad63625a56dc_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490664.850 5322016.700 548.470 4490664.850 5322016.700 555.226 4490671.290 5322015.790 555.226 4490671.290 5322015.790 548.470 4490664.850 5322016.700 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:WallSurface>
            </boundary>
            <boundary>
                <con:WallSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_44e7c68d-da01-4f80-b1a4-9bbde8305c77_msl_N65634">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_44e7c68d-da01-4f80-b1a4-9bbde8305c77_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490656.770 5322017.800 548.470 4490656.770 5322017.800 555.242 4490664.850 5322016.660 555.241 4490664.850 5322016.660 548.470 4490656.770 5322017.800 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:WallSurface>
            </boundary>
            <boundary>
                <con:WallSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_1e36b54e-2518-4afe-a2b4-a59ddff93581_msl_N65646">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_1e36b54e-2518-4afe-a2b4-a59ddff93581_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490663.250 5322006.210 548.470 4490663.250 5322006.210 554.643 4490663.450 5322007.590 555.191 4490663.450 5322007.590 548.470 4490663.250 5322006.210 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:WallSurface>
            </boundary>
            <boundary>
                <con:WallSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_887068cb-0fcb-45f3-b436-d1a1bdef047f_msl_N65658">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_887068cb-0fcb-45f3-b436-d1a1bdef047f_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490663.450 5322007.590 548.470 4490663.450 5322007.590 555.191 4490655.500 5322008.750 555.206 4490655.500 5322008.750 548.470 4490663.450 5322007.590 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:WallSurface>
            </boundary>
            <boundary>
                <con:WallSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_80ce6c2a-8724-4a2a-89e4-881da9530ecc_msl_N65670">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_80ce6c2a-8724-4a2a-89e4-881da9530ecc_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490670.002 5322006.703 555.206 4490669.800 5322005.280 554.641 4490669.800 5322005.280 548.470 4490670.002 5322006.703 548.470 4490670.649 5322011.271 548.470 4490671.290 5322015.790 548.470 4490671.290 5322015.790 555.226 4490670.649 5322011.271 557.020 4490670.002 5322006.703 555.206</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:WallSurface>
            </boundary>
            <boundary>
                <con:WallSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_392cb098-6e22-4334-9853-1e8225966156_msl_N65682">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_392cb098-6e22-4334-9853-1e8225966156_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490666.840 5322005.700 548.470 4490669.800 5322005.280 548.470 4490669.800 5322005.280 554.641 4490666.840 5322005.700 554.642 4490663.250 5322006.210 554.643 4490663.250 5322006.210 548.470 4490666.840 5322005.700 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:WallSurface>
            </boundary>
            <boundary>
                <con:RoofSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_26de5877-57e7-429d-9b9a-274b8ed6aac5_msl_N65694">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_26de5877-57e7-429d-9b9a-274b8ed6aac5_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490670.649 5322011.271 557.020 4490671.290 5322015.790 555.226 4490664.850 5322016.700 555.226 4490664.850 5322016.660 555.241 4490656.770 5322017.800 555.242 4490656.141 5322013.320 557.020 4490670.649 5322011.271 557.020</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:RoofSurface>
            </boundary>
            <boundary>
                <con:WallSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_dd1b367c-c6d8-4eb2-abe6-0accb0fa91b8_msl_N65706">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_dd1b367c-c6d8-4eb2-abe6-0accb0fa91b8_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490655.500 5322008.750 555.206 4490656.141 5322013.320 557.020 4490656.770 5322017.800 555.242 4490656.770 5322017.800 548.470 4490656.141 5322013.320 548.470 4490655.500 5322008.750 548.470 4490655.500 5322008.750 555.206</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:WallSurface>
            </boundary>
            <boundary>
                <con:GroundSurface>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="DEBY_LOD2_5744682_58e93bde-fd64-4fec-9626-5824c2e94f0e_msl_N65718">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="DEBY_LOD2_5744682_58e93bde-fd64-4fec-9626-5824c2e94f0e_poly">
                                    <gml:exterior>
                                        <gml:LinearRing>
                                            <gml:posList>4490670.649 5322011.271 548.470 4490670.002 5322006.703 548.470 4490669.800 5322005.280 548.470 4490666.840 5322005.700 548.470 4490663.250 5322006.210 548.470 4490663.450 5322007.590 548.470 4490655.500 5322008.750 548.470 4490656.141 5322013.320 548.470 4490656.770 5322017.800 548.470 4490664.850 5322016.660 548.470 4490664.850 5322016.700 548.470 4490671.290 5322015.790 548.470 4490670.649 5322011.271 548.470</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:GroundSurface>
            </boundary>
            <bldg:function>31001_9998</bldg:function>
            <bldg:roofType>3100</bldg:roofType>
            <bldg:address>
                <Address gml:id="fme-gen-0355784d-2ffc-4c46-b812-c4d08d6a3f81">
                    <xalAddress>
                        <xAL:AddressDetails>
                            <xAL:Country>
                                <xAL:CountryName>Germany</xAL:CountryName>
                                <xAL:Locality Type="Town">
                                    <xAL:LocalityName>Moosach</xAL:LocalityName>
                                    <xAL:Thoroughfare Type="Street">
                                        <xAL:ThoroughfareName>Am Hang 15</xAL:ThoroughfareName>
                                    </xAL:Thoroughfare>
                                </xAL:Locality>
                            </xAL:Country>
                        </xAL:AddressDetails>
                    </xalAddress>
                </Address>
            </bldg:address>
        </bldg:Building>
    </cityObjectMember>
</CityModel>
